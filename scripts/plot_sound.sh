#!/usr/bin/env bash
# Charts an impact sound (`vroc run --sound X.wav`, docs/hmd.md#impact-sound) against its events:
# the waveform with each event of X_events.csv drawn at its time as a stem of height impulse
# (sounded red, quiet grey, refractory orange; right axis), and below, the first sounded impact
# zoomed to samples with its event time, to show that the onset is at the event to the sample.
#
# Usage: scripts/plot_sound.sh SOUND.wav [OUT.png]
#   SOUND.wav   mono 16-bit WAV written by vroc; its events are read from <stem>_events.csv
#   OUT.png     default: SOUND.png next to the WAV
# Needs python3 (standard library `wave` only) and gnuplot (pngcairo).
set -euo pipefail
[[ $# -ge 1 && $# -le 2 ]] || { sed -n '2,10p' "$0" >&2; exit 2; }
wav=$1
events="${wav%.*}_events.csv"
png=${2:-${wav%.*}.png}
[[ -f "$wav" ]] || { echo "plot_sound: $wav: no such file" >&2; exit 2; }
[[ -f "$events" ]] || { echo "plot_sound: $events: no such file (written by vroc next to the WAV)" >&2; exit 2; }
work=$(mktemp -d /tmp/vroc-plot-sound.XXXXXX)
trap 'rm -rf "$work"' EXIT

# Waveform as t,sample (min and max per bin of a long track, so the envelope survives), the events
# by status as t,impulse, and the zoom window around the first sounded impact.
python3 - "$wav" "$events" "$work" <<'EOF'
import csv, struct, sys, wave
wav_path, events_path, work = sys.argv[1:4]
with wave.open(wav_path, "rb") as w:
    if w.getnchannels() != 1 or w.getsampwidth() != 2:
        sys.exit(f"plot_sound: {wav_path}: expected mono 16-bit PCM")
    rate, frames = w.getframerate(), w.getnframes()
    data = struct.unpack(f"<{frames}h", w.readframes(frames))
samples = [v / 32767.0 for v in data]
bin_size = max(1, len(samples) // 4000)
with open(f"{work}/wave.dat", "w") as out:
    for start in range(0, len(samples), bin_size):
        chunk = samples[start:start + bin_size]
        lo, hi = min(chunk), max(chunk)
        if bin_size == 1:
            out.write(f"{start / rate} {lo}\n")
        else:
            out.write(f"{start / rate} {lo}\n{(start + bin_size / 2) / rate} {hi}\n")
first = None
files = {s: open(f"{work}/{s}.dat", "w") for s in ("sounded", "quiet", "refractory")}
for row in csv.DictReader(open(events_path)):
    files[row["status"]].write(f"{row['t']} {row['impulse']}\n")
    if first is None and row["status"] == "sounded":
        first = float(row["t"])
for f in files.values():
    f.write("nan nan\n")   # every file plots, even with no rows of its status
    f.close()
first = 0.0 if first is None else first
n0, n1 = max(0, int((first - 0.0005) * rate)), min(len(samples), int((first + 0.0020) * rate) + 1)
with open(f"{work}/zoom.dat", "w") as out:
    for n in range(n0, n1):
        out.write(f"{(n / rate - first) * 1e3} {samples[n]}\n")
with open(f"{work}/vars.gp", "w") as out:
    out.write(f"first_t = {first!r}\nrate = {rate}\nduration = {len(samples) / rate!r}\n")
EOF

gnuplot <<EOF
load "$work/vars.gp"
set terminal pngcairo size 1400,900 font "DejaVu Sans,11"
set output "$png"
set multiplot layout 2,1 title "$(basename "$wav"): waveform and collision events" noenhanced
set xlabel "time [s]"
set ylabel "sample [full scale]"
set y2label "event impulse [N s]"
set xrange [0:duration]
set yrange [-1:1]
set y2range [0:*]
set ytics nomirror
set y2tics
set grid
set key top right
plot "$work/wave.dat" using 1:2 with lines lc rgb "#1f4e9a" title "waveform", \
     "$work/sounded.dat" using 1:2 axes x1y2 with impulses lw 2 lc rgb "#d62728" title "event, sounded", \
     "$work/sounded.dat" using 1:2 axes x1y2 with points pt 7 ps 0.8 lc rgb "#d62728" notitle, \
     "$work/quiet.dat" using 1:2 axes x1y2 with impulses lw 2 lc rgb "#999999" title "event, quiet (below 2 m g dt)", \
     "$work/refractory.dat" using 1:2 axes x1y2 with impulses lw 2 lc rgb "#ff7f0e" title "event, refractory"
unset y2label
unset y2tics
set xlabel sprintf("time after the first sounded event (t = %.6f s) [ms]; one sample = %.4f ms", first_t, 1000.0 / rate)
set xrange [-0.5:2.0]
set yrange [*:*]
set arrow 1 from 0, graph 0 to 0, graph 1 nohead lw 2 lc rgb "#d62728"
plot "$work/zoom.dat" using 1:2 with linespoints pt 7 ps 0.6 lc rgb "#1f4e9a" title "samples (event time: red line)"
unset multiplot
EOF
echo "plot_sound: wrote $png"
