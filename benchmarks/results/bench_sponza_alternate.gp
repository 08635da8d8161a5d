# Drawn by `vct bench` (vct bench benchmarks/sweeps/sponza_alternate.json); run `gnuplot bench_sponza_alternate.gp` in this folder to draw it again.
set terminal pngcairo size 2100,700 enhanced font 'DejaVu Sans,10'
set output "bench_sponza_alternate.png"
$engine << EOD
3949 0.035301 0.0181193 "step 0.75"
4012 0.0368192 0.0195 "offset 2.5"
4040 0.0363432 0.0191841 "offset 1"
4076 0.0364575 0.019122 "step 0.35"
4082 0.0358381 0.0182614 "aperture 0.85"
4108 0.0369357 0.0195485 "aperture 1.25"
4125 0.0350199 0.0208033 "lift 0.5"
4127 0.0361359 0.0189119 "default"
4137 0.0374705 0.0260857 "lift 1"
4423 0.0358393 0.0179367 "cones 9"
4899 0.0351497 0.0165873 "cones 16"
EOD
$pathtracer << EOD
91.51 0.105181 0.0779611 "1"
144.7 0.0759862 0.055088 "2"
237.1 0.0543185 0.0386856 "4"
487.8 0.0391672 0.0275592 "8"
1015 0.0278523 0.0195532 "16"
1856 0.0197627 0.0140643 "32"
3645 0.0142802 0.0101104 "64"
7286 0.0104036 0.00737476 "128"
EOD
$pareto << EOD
3949 0.035301 0.0181193 "step 0.75"
4125 0.0350199 0.0208033 "lift 0.5"
EOD
$paretoIndirect << EOD
3949 0.035301 0.0181193 "step 0.75"
4423 0.0358393 0.0179367 "cones 9"
4899 0.0351497 0.0165873 "cones 16"
EOD
$default << EOD
4127 0.0361359 0.0189119 "default"
EOD
set xtics ("1" 1, "2" 2, "5" 5, "10" 10, "20" 20, "50" 50, "100" 100, "200" 200, "500" 500, "1000" 1000, "2000" 2000, "5000" 5000, "10000" 10000, "20000" 20000, "50000" 50000, "100000" 100000, "200000" 200000, "500000" 500000)
noise = 0.00346966
set multiplot layout 1,3 title "sponza 320x180: error against time, vct settings and the path tracer (1 bounce, reference 1024 spp), llvmpipe (LLVM 15.0.6, 256 bits), 2026-11-24" font ',12'
set logscale xy
set grid xtics ytics mxtics mytics lc rgb '#e0e0e0'
set xlabel 'time (ms, log): vct full warm frame / path-tracer render, same CPU'
set key bottom left box opaque font ',9'
set offsets graph 0.08, graph 0.25, graph 0.1, graph 0.1
set autoscale fix
set ytics ("0.0001" 0.0001, "0.0002" 0.0002, "0.0005" 0.0005, "0.001" 0.001, "0.002" 0.002, "0.005" 0.005, "0.01" 0.01, "0.02" 0.02, "0.05" 0.05, "0.1" 0.1, "0.2" 0.2, "0.5" 0.5, "1" 1, "2" 2, "5" 5, "10" 10, "20" 20, "50" 50)
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
set xrange [3037.33:8817.73]
set yrange [0.0348238:0.0376666]
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
