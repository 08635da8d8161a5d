# Drawn by `vct bench` (vct bench benchmarks/sweeps/sponza.json); run `gnuplot bench_sponza.gp` in this folder to draw it again.
set terminal pngcairo size 2100,700 enhanced font 'DejaVu Sans,10'
set output "bench_sponza.png"
$engine << EOD
303 0.0435554 0.0315058 "GI off"
2352 0.0373687 0.0191923 "L7"
3173 0.0428229 0.0175117 "light view 1024"
3342 0.0390983 0.0226018 "no bricks"
3372 0.0390076 0.0233565 "lift 0.5"
3439 0.0407055 0.026889 "lift 1"
3792 0.0370104 0.0173505 "offset 2.5"
4019 0.0364424 0.016923 "step 0.75"
4021 0.0366727 0.0171079 "aperture 0.85"
4050 0.03686 0.0175313 "offset 1"
4090 0.036991 0.0177875 "step 0.35"
4113 0.0368218 0.0174933 "default"
4131 0.0368132 0.016559 "cones 9"
4150 0.037151 0.0180678 "aperture 1.25"
5112 0.0366705 0.0163886 "cones 16"
1.265e+04 0.0364477 0.017305 "L9"
EOD
$pathtracer << EOD
39.33 0.100835 0.0784821 "1"
77.49 0.0739538 0.0558578 "2"
153.9 0.0538767 0.0398237 "4"
306.6 0.0381771 0.0281439 "8"
603.1 0.0270293 0.0199341 "16"
1204 0.0192244 0.0143022 "32"
2398 0.0138297 0.0101892 "64"
4871 0.0101798 0.00746945 "128"
EOD
$pareto << EOD
303 0.0435554 0.0315058 "GI off"
2352 0.0373687 0.0191923 "L7"
3792 0.0370104 0.0173505 "offset 2.5"
4019 0.0364424 0.016923 "step 0.75"
EOD
$paretoIndirect << EOD
303 0.0435554 0.0315058 "GI off"
2352 0.0373687 0.0191923 "L7"
3173 0.0428229 0.0175117 "light view 1024"
3792 0.0370104 0.0173505 "offset 2.5"
4019 0.0364424 0.016923 "step 0.75"
4131 0.0368132 0.016559 "cones 9"
5112 0.0366705 0.0163886 "cones 16"
EOD
$default << EOD
4113 0.0368218 0.0174933 "default"
EOD
set xtics ("1" 1, "2" 2, "5" 5, "10" 10, "20" 20, "50" 50, "100" 100, "200" 200, "500" 500, "1000" 1000, "2000" 2000, "5000" 5000, "10000" 10000, "20000" 20000, "50000" 50000, "100000" 100000, "200000" 200000, "500000" 500000, "1e+06" 1e+06, "2e+06" 2e+06, "5e+06" 5e+06)
noise = 0.00336886
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
set xtics ("10" 10, "20" 20, "50" 50, "100" 100, "200" 200, "500" 500, "1000" 1000, "2000" 2000, "5000" 5000, "10000" 10000, "20000" 20000, "50000" 50000, "100000" 100000, "200000" 200000, "500000" 500000, "1e+06" 1e+06, "2e+06" 2e+06, "5e+06" 5e+06)
set xrange [233.055:22773.5]
set yrange [0.0358733:0.0441245]
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
