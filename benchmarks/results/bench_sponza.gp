# Drawn by `vct bench` (vct bench benchmarks/sweeps/sponza.json); run `gnuplot bench_sponza.gp` in this folder to draw it again.
set terminal pngcairo size 2100,700 enhanced font 'DejaVu Sans,10'
set output "bench_sponza.png"
$engine << EOD
572.8 0.0434897 0.0314698 "GI off"
2779 0.0485999 0.0373417 "L6"
3790 0.048676 0.0368247 "L7"
4504 0.051026 0.0346322 "light view 1024"
4980 0.0461831 0.0330645 "aperture 1.25"
5005 0.0464353 0.0341191 "step 0.35"
5042 0.045651 0.0326123 "cones 9"
5238 0.0467923 0.0347102 "default"
5288 0.0479788 0.0377114 "cones 1"
5425 0.046567 0.0338875 "aperture 0.75"
6151 0.0645339 0.0347326 "light view 512"
6808 0.0460106 0.0339729 "step 1"
7185 0.0497275 0.0389753 "no bricks"
8197 0.0440681 0.0301965 "cones 16"
1.121e+04 0.0463571 0.0339619 "L9"
EOD
$pathtracer << EOD
145.9 0.100817 0.0784584 "1"
279.5 0.0738977 0.0558267 "2"
390.5 0.0538235 0.0397779 "4"
769.2 0.0381158 0.0280854 "8"
1547 0.0269262 0.0198476 "16"
3045 0.0190433 0.0141768 "32"
9131 0.0136022 0.0100257 "64"
1.707e+04 0.00987063 0.00723786 "128"
EOD
$pareto << EOD
572.8 0.0434897 0.0314698 "GI off"
EOD
$paretoIndirect << EOD
572.8 0.0434897 0.0314698 "GI off"
8197 0.0440681 0.0301965 "cones 16"
EOD
$default << EOD
5238 0.0467923 0.0347102 "default"
EOD
set xtics ("10" 10, "20" 20, "50" 50, "100" 100, "200" 200, "500" 500, "1000" 1000, "2000" 2000, "5000" 5000, "10000" 10000, "20000" 20000, "50000" 50000, "100000" 100000, "200000" 200000, "500000" 500000, "1e+06" 1e+06, "2e+06" 2e+06, "5e+06" 5e+06)
noise = 0.00238288
set multiplot layout 1,3 title "sponza 320x180: error against time, vct settings and the path tracer (1 bounce, reference 2048 spp), llvmpipe (LLVM 15.0.6, 256 bits), 2026-11-21" font ',12'
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
     $engine using 1:2:4 with labels left offset char 0.6,0.35 font ',8' notitle, \
     $default using 1:2 with points pt 6 ps 2.4 lw 2 lc rgb 'black' title 'vct default', \
     noise with lines dt 3 lc rgb '#808080' title 'reference noise (est.)'
set ytics ("0.0001" 0.0001, "0.0002" 0.0002, "0.0005" 0.0005, "0.001" 0.001, "0.002" 0.002, "0.005" 0.005, "0.01" 0.01, "0.02" 0.02, "0.05" 0.05, "0.1" 0.1, "0.2" 0.2, "0.5" 0.5, "1" 1, "2" 2, "5" 5)
set ylabel 'RMSE of the indirect part vs reference (linear, log)'
set title 'indirect part alone (final − direct)'
plot $pathtracer using 1:3 with linespoints pt 5 ps 0.8 lw 1.5 lc rgb '#d62728' title 'path tracer (spp)', \
     $pathtracer using 1:3:(sprintf('%s spp', strcol(4))) with labels offset char 0,-0.9 font ',8' tc rgb '#d62728' notitle, \
     $paretoIndirect using 1:3 with linespoints pt 4 ps 1.9 lw 2 dt 2 lc rgb '#1f77b4' title 'Pareto front (vct)', \
     $engine using 1:3 with points pt 7 ps 1.0 lc rgb '#1f77b4' title 'vct settings', \
     $engine using 1:3:4 with labels left offset char 0.6,0.35 font ',8' notitle, \
     $default using 1:3 with points pt 6 ps 2.4 lw 2 lc rgb 'black' title 'vct default', \
     noise with lines dt 3 lc rgb '#808080' title 'reference noise (est.)'
set offsets 0, 0, 0, 0
unset logscale y
set ytics auto
set format y '%g'
set xtics ("10" 10, "20" 20, "50" 50, "100" 100, "200" 200, "500" 500, "1000" 1000, "2000" 2000, "5000" 5000, "10000" 10000, "20000" 20000, "50000" 50000, "100000" 100000, "200000" 200000, "500000" 500000, "1e+06" 1e+06, "2e+06" 2e+06, "5e+06" 5e+06)
set xrange [440.58:20170]
set yrange [0.0418062:0.0662175]
set key top left box opaque font ',9'
set ylabel 'RMSE of the full image vs reference (linear)'
set title 'vct points only (zoom; full image)'
plot $pareto using 1:2 with linespoints pt 4 ps 1.9 lw 2 dt 2 lc rgb '#1f77b4' title 'Pareto front (vct)', \
     $engine using 1:2 with points pt 7 ps 1.0 lc rgb '#1f77b4' notitle, \
     $engine using 1:2:4 with labels left offset char 0.6,0.35 font ',8' notitle, \
     $default using 1:2 with points pt 6 ps 2.4 lw 2 lc rgb 'black' title 'vct default', \
     $pathtracer using 1:2 with linespoints pt 5 ps 0.8 lw 1.5 lc rgb '#d62728' notitle, \
     $pathtracer using 1:2:(sprintf('%s spp', strcol(4))) with labels offset char 0,-0.9 font ',8' tc rgb '#d62728' notitle
unset multiplot
