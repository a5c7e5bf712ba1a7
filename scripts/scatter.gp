# scatter.gp: predicted against observed digital counts, one colour per class, with the
# 1:1 line. gnuplot -e "data='PAIRS.txt'; out='OUT.png'; title='...'" scripts/scatter.gp,
# PAIRS.txt from landsat_scene pairs (rows: class synthetic reference).
set terminal pngcairo size 520,480 noenhanced font ",10"
set output out
set title title
set xlabel "observed DN (Landsat)"
set ylabel "predicted DN (sigchain)"
set key top left
set size square
stats data using 3 nooutput
lo = STATS_min
hi = STATS_max
stats data using 2 nooutput
lo = (STATS_min < lo) ? STATS_min : lo
hi = (STATS_max > hi) ? STATS_max : hi
set xrange [lo:hi]
set yrange [lo:hi]
classes = system("awk '!/^#/ { print $1 }' " . data . " | sort -u | tr '\\n' ' '")
plot for [c in classes] data using (strcol(1) eq c ? $3 : NaN):2 with points pt 7 ps 0.3 title c, \
     x with lines lc rgb "black" dt 2 title "1:1"
