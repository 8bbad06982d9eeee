#!/usr/bin/env bash
# FFT benchmark (issue 18): time per evaluation of a PD operator on a uniform periodic grid, the FFT
# form (FFT::FftOperator, FFTW_MEASURE plans) against the library's direct neighbour sum
# (FFT::DirectOperator), one thread, for N = 2^k nodes and horizon factors m = delta / spacing:
#   3D: k = 15..21, 2D: k = 14, 16, ..., 22; m = 3, 4, 5, 6, 8, 10; linear bond based and LPS;
#   the nonlinear bond-based model at m = 5 on three sizes.
# The direct sum is timed on min(N, 2^15) nodes (3D) or min(N, 2^16) (2D) and scaled to N (its cost
# per node does not depend on N: the bonds are grid offsets); one full-size direct run per dimension
# checks that scaling. Extra rows: the crossover (m = 1, 1.5, 2), two threads and two MPI ranks at 3D,
# N = 2^21.
# Writes doc/benchmarks/fft.csv (the sweep), fft_extra.csv (check, crossover, threads),
# fft_memory.csv (bytes per node and time, mask fields kept and recomputed) and, when
# pdfem-plot is built, the charts fft_time_3d.png, fft_time_2d.png, fft_speedup.png and
# fft_crossover.png.
#
# usage: applications/benchmarks/fft/run.sh [BUILD_DIR] [OUT_DIR]
#   SECONDS_PER_POINT=0.3 (time spent per measurement; best of the repetitions in it).
source "$(dirname "${BASH_SOURCE[0]}")/../common.sh" "${1:-}" "${2:-}"

bench="$build/bin/pdfem_fft_benchmark"
s=${SECONDS_PER_POINT:-0.3}
csv="$out/fft.csv"
extra="$out/fft_extra.csv"
memory="$out/fft_memory.csv"
ms=3,4,5,6,8,10

# Memory against time (fft_memory.csv): each model with its mask fields kept and recomputed
# (--lean, FftOptions::keep_mask_fields = false), m = 5, 3D N = 2^21 and 2D N = 2^22, the runs of
# one size alternated; the body filling the box, then a block with a gap of one horizon (--body
# block: the kept fields are stored on the layer near its faces; the direct sum on the full grid
# with the same mask). MEMORY_ONLY=1 writes this table only.
{
  "$bench" --header --dim 3 --model linear --log2n 15 --m 5 --seconds 0 --no-direct | head -n 1
  for dim in 3 2; do
    if [ "$dim" = 3 ]; then k=21; d=15; else k=22; d=16; fi
    for model in linear lps nonlinear; do
      "$bench" --dim $dim --model $model --log2n $k --m 5 --direct-log2 $d --seconds "$s"
      "$bench" --dim $dim --model $model --log2n $k --m 5 --direct-log2 $d --seconds "$s" --lean
      "$bench" --dim $dim --model $model --log2n $k --m 5 --direct-log2 $k --seconds "$s" --body block
      "$bench" --dim $dim --model $model --log2n $k --m 5 --no-direct --seconds "$s" --body block --lean
    done
  done
} | tee "$memory"
[ "${MEMORY_ONLY:-0}" = 1 ] && exit 0

"$bench" --header --dim 3 --model linear --log2n 15,16,17,18,19,20,21 --m $ms --seconds "$s" | tee "$csv"
"$bench" --dim 3 --model lps --log2n 15,16,17,18,19,20,21 --m $ms --seconds "$s" | tee -a "$csv"
"$bench" --dim 3 --model nonlinear --log2n 15,18,21 --m 5 --seconds "$s" | tee -a "$csv"
"$bench" --dim 2 --model linear --log2n 14,16,18,20,22 --m $ms --direct-log2 16 --seconds "$s" | tee -a "$csv"
"$bench" --dim 2 --model lps --log2n 14,16,18,20,22 --m $ms --direct-log2 16 --seconds "$s" | tee -a "$csv"
"$bench" --dim 2 --model nonlinear --log2n 14,18,22 --m 5 --direct-log2 16 --seconds "$s" | tee -a "$csv"

{
  echo "set,$(head -n 1 "$csv")"
  # the direct sum on the full grid (no scaling), to check the per-node scaling of the sweep
  "$bench" --dim 3 --model lps --log2n 18 --m 5 --direct-log2 18 --seconds "$s" | sed 's/^/check,/'
  "$bench" --dim 2 --model lps --log2n 20 --m 5 --direct-log2 20 --seconds "$s" | sed 's/^/check,/'
  # small horizons: where the direct sum catches up
  "$bench" --dim 3 --model lps --log2n 15,18,21 --m 1,1.5,2 --seconds "$s" | sed 's/^/crossover,/'
  "$bench" --dim 2 --model lps --log2n 14,18,22 --m 1,1.5,2 --direct-log2 16 --seconds "$s" |
    sed 's/^/crossover,/'
  # two threads (FFTW's threaded plans; the direct sum's rows on two threads)
  "$bench" --dim 3 --model lps --log2n 21 --m 5 --threads 2 --seconds "$s" | sed 's/^/threads,/'
  "$bench" --dim 3 --model linear --log2n 21 --m 5 --threads 2 --seconds "$s" | sed 's/^/threads,/'
  # two ranks of one thread (slabs of the box, FFTW's MPI plans; no direct sum)
  if command -v mpirun > /dev/null; then
    mpirun -np 2 "$bench" --dim 3 --model lps --log2n 21 --m 5 --seconds "$s" | sed 's/^/mpi,/'
  fi
} | tee "$extra"

if have_plot; then
  # one column per m (the FFT's time does not depend on m: its m = 5 row is drawn)
  python3 - "$csv" "$extra" "$work" << 'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
extra = list(csv.DictReader(open(sys.argv[2])))
work = sys.argv[3]
def table(name, header, lines):
    with open("%s/%s.csv" % (work, name), "w") as f:
        f.write(",".join(header) + "\n")
        for l in lines:
            f.write(",".join(str(v) for v in l) + "\n")
for dim in ("2", "3"):
    for model in ("lps", "linear bond based"):
        sel = [r for r in rows if r["dim"] == dim and r["model"] == model]
        sizes = sorted({int(r["nodes"]) for r in sel})
        get = lambda n, m, c: next((r[c] for r in sel if int(r["nodes"]) == n and float(r["m"]) == m), "")
        tag = "%s_%s" % (dim, "lps" if model == "lps" else "linear")
        table("time_" + tag, ["nodes", "fft", "direct_m3", "direct_m5", "direct_m10"],
              [[n, get(n, 5, "fft_seconds"), get(n, 3, "direct_seconds"), get(n, 5, "direct_seconds"),
                get(n, 10, "direct_seconds")] for n in sizes])
        table("speedup_" + tag, ["nodes", "m3", "m5", "m10"],
              [[n, get(n, 3, "speedup"), get(n, 5, "speedup"), get(n, 10, "speedup")] for n in sizes])
# speed-up against m for the smallest and largest 3D grid (LPS), crossover rows included
allrows = rows + [r for r in extra if r["set"] == "crossover"]
for dim, small, large in (("3", 32768, 2097152), ("2", 16384, 4194304)):
    sel = [r for r in allrows if r["dim"] == dim and r["model"] == "lps"]
    ms = sorted({float(r["m"]) for r in sel})
    get = lambda n, m: next((r["speedup"] for r in sel if int(r["nodes"]) == n and float(r["m"]) == m), "")
    table("crossover_%s" % dim, ["m", "small", "large"], [[m, get(small, m), get(large, m)] for m in ms])
PY
  for dim in 3 2; do
    xvfb-run -a "$plot" chart "$work/time_${dim}_lps.csv" --x nodes --y fft,direct_m3,direct_m5,direct_m10 \
      --csv2 "$work/time_${dim}_linear.csv" --logx --logy --points \
      --label "LPS FFT,LPS direct m=3,LPS direct m=5,LPS direct m=10,BB FFT,BB direct m=3,BB direct m=5,BB direct m=10" \
      --xlabel "grid nodes N" --ylabel "seconds per evaluation" \
      --title "${dim}D: one operator evaluation, FFT against the direct sum (1 thread)" \
      --out "$out/fft_time_${dim}d.png"
  done
  xvfb-run -a "$plot" chart "$work/speedup_3_lps.csv" --x nodes --y m3,m5,m10 --csv2 "$work/speedup_2_lps.csv" \
    --logx --logy --points --label "3D m=3,3D m=5,3D m=10,2D m=3,2D m=5,2D m=10" \
    --xlabel "grid nodes N" --ylabel "direct time / FFT time" \
    --title "LPS: speed-up of the FFT form over the direct sum (1 thread)" --out "$out/fft_speedup.png"
  xvfb-run -a "$plot" chart "$work/crossover_3.csv" --x m --y small,large --csv2 "$work/crossover_2.csv" \
    --logy --points --label "3D N=2^15,3D N=2^21,2D N=2^14,2D N=2^22" \
    --xlabel "horizon factor m = delta / spacing" --ylabel "direct time / FFT time" \
    --title "LPS: speed-up against the horizon (1 = crossover)" --out "$out/fft_crossover.png"
  echo "charts: $out/fft_time_3d.png, fft_time_2d.png, fft_speedup.png, fft_crossover.png"
else
  echo "pdfem-plot or xvfb-run missing: no charts (see doc/tools.md)"
fi
