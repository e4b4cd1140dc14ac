set terminal svg size 960,540 dynamic font 'sans,11' background rgb 'white'
set output 'pareto-stack20_ratio10.svg'
set termoption noenhanced
set title 'stack20_ratio10: speed against accuracy (4 s simulated, median of 3 run(s); lower left is better)'
set xlabel 'total step time [s] (sum of stepFrame wall times, log)'
set ylabel 'creep after 1 s [mm] (log; * = below 0.001 mm, drawn at it)'
set logscale xy
set xrange [0.006334933333333327:0.11510091600000004]
set yrange [0.0003333333333333333:64204.03114053757]
set format x '%g'
set format y '%g'
set grid
set key outside right top box
plot 'pareto-stack20_ratio10.dat' index 3 using 1:2 with steps lw 1.5 dt 2 lc rgb 'gray30' title 'Pareto front', \
     'pareto-stack20_ratio10.dat' index 0 using 1:2 with points pt 7 ps 1.3 lc rgb '#1f77b4' title 'native', \
     'pareto-stack20_ratio10.dat' index 0 using 1:2:($3-$1):($4-$2) with vectors nohead lw 0.5 lc rgb '#1f77b4' notitle, \
     'pareto-stack20_ratio10.dat' index 0 using 3:4:5 with labels left offset char 0.5,0.75 font ',9' tc rgb '#1f77b4' notitle, \
     'pareto-stack20_ratio10.dat' index 1 using 1:2 with points pt 7 ps 1.3 lc rgb '#d62728' title 'bullet', \
     'pareto-stack20_ratio10.dat' index 1 using 1:2:($3-$1):($4-$2) with vectors nohead lw 0.5 lc rgb '#d62728' notitle, \
     'pareto-stack20_ratio10.dat' index 1 using 3:4:5 with labels left offset char 0.5,0.75 font ',9' tc rgb '#d62728' notitle, \
     'pareto-stack20_ratio10.dat' index 2 using 1:2 with points pt 7 ps 1.3 lc rgb '#2ca02c' title 'ode', \
     'pareto-stack20_ratio10.dat' index 2 using 1:2:($3-$1):($4-$2) with vectors nohead lw 0.5 lc rgb '#2ca02c' notitle, \
     'pareto-stack20_ratio10.dat' index 2 using 3:4:5 with labels left offset char 0.5,0.75 font ',9' tc rgb '#2ca02c' notitle
