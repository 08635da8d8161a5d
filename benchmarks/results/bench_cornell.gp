# Drawn by `vct bench` (vct bench benchmarks/sweeps/cornell.json); run `gnuplot bench_cornell.gp` in this folder to draw it again.
set terminal pngcairo size 2100,700 enhanced font 'DejaVu Sans,10'
set output "bench_cornell.png"
$engine << EOD
115.5 0.0711056 0.06987 "GI off"
498.3 0.0319596 0.0288147 "L6"
806.8 0.0319864 0.0289377 "L7"
2059 0.0334813 0.0304275 "light view 1024"
2196 0.0332419 0.0304522 "offset 1"
2207 0.0340493 0.0312429 "step 0.75"
2209 0.0343596 0.0303624 "light view 512"
2229 0.0332162 0.0304173 "default"
2414 0.0329166 0.0301101 "offset 2.5"
2428 0.0312719 0.028158 "lift 0.5"
2430 0.0434686 0.041409 "lift 1"
2461 0.0329088 0.029958 "step 0.35"
2598 0.0425671 0.0404994 "no bricks"
2666 0.0340906 0.0313147 "aperture 1.25"
2708 0.0322475 0.0293704 "aperture 0.85"
2744 0.0307197 0.0276195 "cones 6"
2867 0.0275179 0.0239454 "cones 9"
2952 0.0705469 0.0693117 "cones 1"
3875 0.0248549 0.0209909 "cones 16"
8345 0.033945 0.0312454 "L9"
EOD
$pathtracer << EOD
9.961 0.152846 0.152266 "1"
20.17 0.106638 0.105955 "2"
40.56 0.0747809 0.0742655 "4"
81.46 0.0533364 0.0529291 "8"
163.4 0.0376246 0.0373476 "16"
325.9 0.0264832 0.0262843 "32"
650.3 0.0189356 0.0188115 "64"
1305 0.0134033 0.0133121 "128"
2627 0.0096764 0.00960391 "256"
EOD
$pareto << EOD
115.5 0.0711056 0.06987 "GI off"
498.3 0.0319596 0.0288147 "L6"
2428 0.0312719 0.028158 "lift 0.5"
2744 0.0307197 0.0276195 "cones 6"
2867 0.0275179 0.0239454 "cones 9"
3875 0.0248549 0.0209909 "cones 16"
EOD
$paretoIndirect << EOD
115.5 0.0711056 0.06987 "GI off"
498.3 0.0319596 0.0288147 "L6"
2428 0.0312719 0.028158 "lift 0.5"
2744 0.0307197 0.0276195 "cones 6"
2867 0.0275179 0.0239454 "cones 9"
3875 0.0248549 0.0209909 "cones 16"
EOD
$default << EOD
2229 0.0332162 0.0304173 "default"
EOD
set xtics ("0.1" 0.1, "0.2" 0.2, "0.5" 0.5, "1" 1, "2" 2, "5" 5, "10" 10, "20" 20, "50" 50, "100" 100, "200" 200, "500" 500, "1000" 1000, "2000" 2000, "5000" 5000, "10000" 10000, "20000" 20000, "50000" 50000, "100000" 100000, "200000" 200000, "500000" 500000)
noise = 0.00233982
set multiplot layout 1,3 title "cornell 320x240: error against time, vct settings and the path tracer (1 bounce, reference 4096 spp), llvmpipe (LLVM 15.0.6, 256 bits), 2026-11-24" font ',12'
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
set ytics ("0.0001" 0.0001, "0.0002" 0.0002, "0.0005" 0.0005, "0.001" 0.001, "0.002" 0.002, "0.005" 0.005, "0.01" 0.01, "0.02" 0.02, "0.05" 0.05, "0.1" 0.1, "0.2" 0.2, "0.5" 0.5, "1" 1, "2" 2, "5" 5, "10" 10, "20" 20, "50" 50)
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
set xtics ("10" 10, "20" 20, "50" 50, "100" 100, "200" 200, "500" 500, "1000" 1000, "2000" 2000, "5000" 5000, "10000" 10000, "20000" 20000, "50000" 50000, "100000" 100000, "200000" 200000, "500000" 500000)
set xrange [88.8161:15021.6]
set yrange [0.0211549:0.0748056]
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
