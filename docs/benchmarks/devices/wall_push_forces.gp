set terminal pngcairo size 1100,500 font ",10"
set termoption noenhanced
set output "wall_push_forces.png"   # run from this folder: gnuplot wall_push_forces.gp
set datafile separator ","
set key top right
set xlabel "time [s]"
set ylabel "force on the hand, -x component [N]"
set title "wall_push (native): force-log trace vs the coupling's closed form k·d (+ c·v while the hand moves)"
set grid
k = (2*pi*5)**2; c = 2*(2*pi*5)
hand(t) = 0.5*(t < 1.2 ? t : 1.2)
cf(t) = t < 0.81 ? 1/0 : k*(hand(t) - 0.4) + (t < 1.2 ? c*0.5 : 0)
plot "wall_push_forces.csv" every ::1 using ($1/1e9):(-$3) with points pt 7 ps 0.6 title "logged by force-log (120 rows)", \
     cf(x) with lines lw 1.5 title "k (x_hand - x_box) + c v, box at the wall (k = 987 N/m, c = 62.8 N s/m)"
