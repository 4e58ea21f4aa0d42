#!/usr/bin/env bash
# Error per sample of the two samplers (core/random.h: sobol, independent) on the Cornell box, against
# a reference made of two independent halves, and the spp each needs to reach Cycles' 64-spp error.
#
#   bench/sampler_compare.sh FLUENCE OUT_DIR [REF_SPP] [SPP...]
#
# FLUENCE is the fluence binary. The reference: two renders of REF_SPP (default 2048) samples with
# the independent sampler, seeds 1 and 2 (kept if present); R their mean, (A - B)^2 / 4 its
# per-pixel variance, subtracted from every squared error (bench/fluence_bench/metrics.py's relMSE,
# computed with oiiotool: this script needs no numpy). Then the series at SPP (default 4 16 64 256
# 1024, seed 0), sobol and independent alternating at each count so that the machine's load falls on
# both alike. Prints and writes OUT_DIR/series.csv: renderer time, relMSE (eps 0.01), relMSE x spp
# (constant for independent samples), and the corrected RMSE over pixels and channels (the metric of
# the Cycles peer's table, shared/peers/cycles/README.md: 0.00804 at 64 spp on this scene) and the
# relative difference of the image mean from the reference's (bias, within the reference's noise).
set -euo pipefail
FLUENCE=$(realpath "$1"); OUT=$2; REF_SPP=${3:-2048}; shift $(( $# < 3 ? $# : 3 ))
SPPS=("$@"); [ ${#SPPS[@]} -gt 0 ] || SPPS=(4 16 64 256 1024)
SCENE=$(realpath "$(dirname "$0")/../usd_samples/cornell_box.usda")
mkdir -p "$OUT"; OUT=$(realpath "$OUT")

render() {  # render SAMPLER SPP SEED OUT.exr -> prints render seconds
    "$FLUENCE" render "$SCENE" -r 256 256 --sampler "$1" --spp "$2" --seed "$3" -j 2 -o "$4" > "${4%.exr}.log" 2>&1
    sed -n 's/.*render \([0-9.]*\) s.*/\1/p' "${4%.exr}.log"
}
mean() {  # mean IMAGE-ARGS... -> the mean over pixels and channels of the image oiiotool's arguments leave
    # (scaled by 1e6 before oiiotool prints it, which it does with six decimals)
    oiiotool "$@" --mulc 1e6 --printstats | sed -n 's/.*Stats Avg: *\([-0-9.e+ ]*\).*/\1/p' |
        awk '{ s = 0; for (i = 1; i <= NF; ++i) s += $i; printf "%.8g\n", s / NF / 1e6 }'
}

for seed in 1 2; do
    [ -s "$OUT/ref_$seed.exr" ] || echo "reference seed $seed: $(render independent "$REF_SPP" "$seed" "$OUT/ref_$seed.exr") s"
done
oiiotool "$OUT/ref_1.exr" --ch R,G,B "$OUT/ref_2.exr" --ch R,G,B --add --mulc 0.5 -d float -o "$OUT/ref_mean.exr"
oiiotool "$OUT/ref_1.exr" --ch R,G,B "$OUT/ref_2.exr" --ch R,G,B --sub --mulc 0.5 --dup --mul -d float -o "$OUT/ref_var.exr"
oiiotool "$OUT/ref_mean.exr" --dup --mul --addc 0.01 -d float -o "$OUT/ref_den.exr"
REF_MSE=$(mean "$OUT/ref_var.exr")
REF_MEAN=$(mean "$OUT/ref_mean.exr")
REF_REL=$(mean "$OUT/ref_var.exr" "$OUT/ref_den.exr" --div)
echo "reference: ${REF_SPP} spp x 2; its own MSE $REF_MSE, relMSE $REF_REL"

echo "sampler,spp,render_s,relmse,relmse_x_spp,rmse,rel_bias" | tee "$OUT/series.csv"
for n in "${SPPS[@]}"; do
    for sampler in sobol independent; do
        img="$OUT/${sampler}_spp$n.exr"
        t=$(render "$sampler" "$n" 0 "$img")
        sq=("$img" --ch R,G,B "$OUT/ref_mean.exr" --sub --dup --mul)
        raw_rel=$(mean "${sq[@]}" "$OUT/ref_den.exr" --div)
        raw_mse=$(mean "${sq[@]}")
        shift_=$(mean "$img" --ch R,G,B "$OUT/ref_mean.exr" --sub)
        awk -v s="$sampler" -v n="$n" -v t="$t" -v r="$raw_rel" -v rr="$REF_REL" -v m="$raw_mse" -v rm="$REF_MSE" \
            -v d="$shift_" -v rmean="$REF_MEAN" 'BEGIN { rel = r - rr; mse = m - rm;
            printf "%s,%s,%s,%.6g,%.6g,%.6g,%.3g\n", s, n, t, rel, rel * n, sqrt(mse > 0 ? mse : 0), d / rmean }' |
            tee -a "$OUT/series.csv"
    done
done
