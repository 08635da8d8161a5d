# Drawn by `vct bench` (vct bench benchmarks/sweeps/sponza_alcove.json); run `gnuplot bench_sponza_alcove.gp` in this folder to draw it again.
set terminal pngcairo size 2100,700 enhanced font 'DejaVu Sans,10'
set output "bench_sponza_alcove.png"
$engine << EOD
3658 0.0159756 0.00600575 "aperture 0.85"
3684 0.016345 0.00701657 "offset 1"
3687 0.0188929 0.0119018 "lift 0.5"
3718 0.0162428 0.00651275 "aperture 1.25"
3742 0.0169581 0.00857868 "lift 1"
3755 0.0155373 0.0050313 "step 0.75"
3795 0.0157836 0.00537316 "offset 2.5"
3814 0.0161045 0.00616596 "step 0.35"
3841 0.0161302 0.00640833 "default"
3970 0.0161292 0.00643427 "cones 9"
4548 0.0159926 0.00608013 "cones 16"
EOD
$pathtracer << EOD
39.78 0.0304418 0.0246546 "1"
104.9 0.0232229 0.0182291 "2"
148.2 0.0161857 0.0125512 "4"
325.8 0.0118078 0.00868531 "8"
611.9 0.00837531 0.00635142 "16"
1318 0.00564766 0.00448059 "32"
2545 0.00418629 0.0031797 "64"
4995 0.00309463 0.00231897 "128"
EOD
$pareto << EOD
3658 0.0159756 0.00600575 "aperture 0.85"
3755 0.0155373 0.0050313 "step 0.75"
EOD
$paretoIndirect << EOD
3658 0.0159756 0.00600575 "aperture 0.85"
3755 0.0155373 0.0050313 "step 0.75"
EOD
$default << EOD
3841 0.0161302 0.00640833 "default"
EOD
set xtics ("1" 1, "2" 2, "5" 5, "10" 10, "20" 20, "50" 50, "100" 100, "200" 200, "500" 500, "1000" 1000, "2000" 2000, "5000" 5000, "10000" 10000, "20000" 20000, "50000" 50000, "100000" 100000, "200000" 200000, "500000" 500000)
noise = 0.00104799
set multiplot layout 1,3 title "sponza 320x180: error against time, vct settings and the path tracer (1 bounce, reference 1024 spp), llvmpipe (LLVM 15.0.6, 256 bits), 2026-11-24" font ',12'
set logscale xy
set grid xtics ytics mxtics mytics lc rgb '#e0e0e0'
set xlabel 'time (ms, log): vct full warm frame / path-tracer render, same CPU'
set key bottom left box opaque font ',9'
set offsets graph 0.08, graph 0.25, graph 0.1, graph 0.1
set autoscale fix
set ytics ("0.0001" 0.0001, "0.0002" 0.0002, "0.0005" 0.0005, "0.001" 0.001, "0.002" 0.002, "0.005" 0.005, "0.01" 0.01, "0.02" 0.02, "0.05" 0.05, "0.1" 0.1, "0.2" 0.2, "0.5" 0.5, "1" 1, "2" 2, "5" 5)
set ylabel 'RMSE of the full image vs reference (linear, log)'
set title 'full image'
plot $pathtracer using 1:2 with linespoints pt 5 ps 0.8 lw 1.5 lc rgb '#d62728' title 'path tracer (spp)', \
     $pathtracer using 1:2:(sprintf('%s spp', strcol(4))) with labels offset char 0,-0.9 font ',8' tc rgb '#d62728' notitle, \
     $pareto using 1:2 with linespoints pt 4 ps 1.9 lw 2 dt 2 lc rgb '#1f77b4' title 'Pareto front (vct)', \
     $engine using 1:2 with points pt 7 ps 1.0 lc rgb '#1f77b4' title 'vct settings', \
     $engine using 1:2:4 with labels left offset char 0.6,0.35 font ',8' noenhanced notitle, \
     $default using 1:2 with points pt 6 ps 2.4 lw 2 lc rgb 'black' title 'vct default', \
     noise with lines dt 3 lc rgb '#808080' title 'reference noise (est.)'
set ytics ("0.0001" 0.0001, "0.0002" 0.0002, "0.0005" 0.0005, "0.001" 0.001, "0.002" 0.002, "0.005" 0.005, "0.01" 0.01, "0.02" 0.02, "0.05" 0.05, "0.1" 0.1, "0.2" 0.2, "0.5" 0.5, "1" 1, "2" 2, "5" 5)
set ylabel 'RMSE of the indirect part vs reference (linear, log)'
set title 'indirect part alone (final − direct)'
plot $pathtracer using 1:3 with linespoints pt 5 ps 0.8 lw 1.5 lc rgb '#d62728' title 'path tracer (spp)', \
     $pathtracer using 1:3:(sprintf('%s spp', strcol(4))) with labels offset char 0,-0.9 font ',8' tc rgb '#d62728' notitle, \
     $paretoIndirect using 1:3 with linespoints pt 4 ps 1.9 lw 2 dt 2 lc rgb '#1f77b4' title 'Pareto front (vct)', \
     $engine using 1:3 with points pt 7 ps 1.0 lc rgb '#1f77b4' title 'vct settings', \
     $engine using 1:3:4 with labels left offset char 0.6,0.35 font ',8' noenhanced notitle, \
     $default using 1:3 with points pt 6 ps 2.4 lw 2 lc rgb 'black' title 'vct default', \
     noise with lines dt 3 lc rgb '#808080' title 'reference noise (est.)'
set offsets 0, 0, 0, 0
unset logscale y
set ytics auto
set format y '%g'
set xtics ("100" 100, "200" 200, "500" 500, "1000" 1000, "2000" 2000, "5000" 5000, "10000" 10000, "20000" 20000, "50000" 50000, "100000" 100000, "200000" 200000, "500000" 500000)
set xrange [2813.85:8186.7]
set yrange [0.0152689:0.0191613]
set key top left box opaque font ',9'
set ylabel 'RMSE of the full image vs reference (linear)'
set title 'vct points only (zoom; full image)'
plot $pareto using 1:2 with linespoints pt 4 ps 1.9 lw 2 dt 2 lc rgb '#1f77b4' title 'Pareto front (vct)', \
     $engine using 1:2 with points pt 7 ps 1.0 lc rgb '#1f77b4' notitle, \
     $engine using 1:2:4 with labels left offset char 0.6,0.35 font ',8' noenhanced notitle, \
     $default using 1:2 with points pt 6 ps 2.4 lw 2 lc rgb 'black' title 'vct default', \
     $pathtracer using 1:2 with linespoints pt 5 ps 0.8 lw 1.5 lc rgb '#d62728' notitle, \
     $pathtracer using 1:2:(sprintf('%s spp', strcol(4))) with labels offset char 0,-0.9 font ',8' tc rgb '#d62728' notitle
unset multiplot
