#!/usr/bin/env bash
# performance_commands.sh MESHPARTICLES MESH WORKDIR PLOT_SCRIPT: the tuning
# loop end to end on a small problem. sweep --save writes the tuning file,
# run takes its sizes from it and says so in report.json, flags override it,
# an unreadable tuning file falls back to the defaults with a warning, bench
# writes its tables, and the plot script turns both JSON files into PNGs.
set -euo pipefail
bin=$1 mesh=$2 work=$3 plot=$4
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
tuning="$work/config/tuning.json"

"$bin" sweep "$mesh" -n 64 --wg 8,16 --tile 16,64 --iterations 2 --csv "$work/sweep.csv" --json "$work/sweep.json" \
  --save --tuning-file "$tuning" -q > "$work/sweep.txt"
grep -q "^best tiled: wg" "$work/sweep.txt" || fail "sweep table has no best tiled line"
grep -q "^best field: wg" "$work/sweep.txt" || fail "sweep table has no best field line"
[ "$(grep -B 2 "^best naive" "$work/sweep.txt" | head -n 1 | awk '{print $4}')" = ok ] || fail "last table row is not a timed one"
head -n 1 "$work/sweep.csv" | grep -q "^device,max_work_group_size,local_memory_bytes,mesh,n,kernel,wg,tile,status,median_ms,min_ms" \
  || fail "sweep CSV header"
[ "$(grep -c ',ok,' "$work/sweep.csv")" -eq 8 ] || fail "expected 8 timed rows in the CSV (naive 2, tiled 4, field 2)"
[ -s "$tuning" ] || fail "sweep --save wrote no tuning file"
saved_wg=$(/usr/bin/python3 -c "import json,sys; e=[e for e in json.load(open(sys.argv[1]))['entries'] if e['kernel']=='tiled'][0]; print(e['wg'])" "$tuning")

"$bin" run "$mesh" -n 64 --iterations 2 --backend tiled --tuning-file "$tuning" --out "$work/run" -q > /dev/null
grep -q '"sizes_from": "tuning file"' "$work/run/report.json" || fail "run did not take the tuning file's sizes"
grep -Eq "\"wg\": $saved_wg,?$" "$work/run/report.json" || fail "run's wg is not the saved $saved_wg"

saved_field_wg=$(/usr/bin/python3 -c "import json,sys; e=[e for e in json.load(open(sys.argv[1]))['entries'] if e['kernel']=='field'][0]; print(e['wg'])" "$tuning")
"$bin" run "$mesh" -n 64 --iterations 2 --backend field --tuning-file "$tuning" --out "$work/run" -q > /dev/null
grep -Eq "\"wg\": $saved_field_wg,?$" "$work/run/report.json" || fail "field run's wg is not the saved $saved_field_wg"
grep -q '"weights": "float"' "$work/run/report.json" || fail "field run's report does not name its weights"

"$bin" run "$mesh" -n 64 --iterations 2 --backend tiled --tuning-file "$tuning" --wg 32 --tile 8 --out "$work/run" -q > /dev/null
grep -q '"sizes_from": "--wg/--tile"' "$work/run/report.json" || fail "flags did not override the tuning file"

echo "not json" > "$work/broken.json"
"$bin" run "$mesh" -n 64 --iterations 2 --method paper --tuning-file "$work/broken.json" --out "$work/run" 2> "$work/warning.txt" > /dev/null
grep -q "warning: tuning file .*broken.json is not readable" "$work/warning.txt" || fail "no warning for a broken tuning file"
grep -q '"sizes_from": "built-in default"' "$work/run/report.json" || fail "broken tuning file: not the built-in default"
if "$bin" sweep "$mesh" -n 64 --wg 8 --tile 16 --iterations 1 --save --tuning-file "$work/broken.json" -q 2> "$work/error.txt" > /dev/null; then
  fail "sweep --save accepted an unreadable tuning file"
fi
[ "$(cat "$work/broken.json")" = "not json" ] || fail "sweep --save overwrote the user's broken file"

"$bin" bench --case torus:64,torus:128 --iterations 2 --tuning-file "$tuning" --csv "$work/bench.csv" \
  --json "$work/bench.json" -q > "$work/bench.txt"
grep -q "^torus (1500 vertices)" "$work/bench.txt" || fail "bench table has no torus block"
grep -Eq "^tiled +\(GPU2\) +[0-9.]+ \[[0-9.]+x\] +- " "$work/bench.txt" || fail "bench tiled row (ours with speed-up, no paper figure at n=64)"
grep -Eq "0\.17 \[90x\]" "$work/bench.txt" || fail "the paper's torus/128 GPU2 figure and speed-up are missing"
grep -Eq "^field +\(vs GPU2\) +[0-9.]+ \[[0-9.]+x\] .* 0\.17 \[90x\]" "$work/bench.txt" || fail "bench field row beside the paper's GPU2"
grep -Eq "^field: times faster than the paper's GPU2 n=128 [0-9.]+x$" "$work/bench.txt" || fail "bench: field against GPU2"
[ "$(grep -c '^' "$work/bench.csv")" -eq 9 ] || fail "expected a header and 8 rows in the bench CSV"

"$plot" "$work/sweep.json" "$work/bench.json" > /dev/null
[ -s "$work/sweep_heatmap.png" ] && [ -s "$work/bench_bench.png" ] || fail "plot_sweep.py wrote no PNG"
echo "ok"
