#!/usr/bin/env bash
# Random walk against diffusion (subsurface scattering, issue #8): error against time on the
# subsurface sample and on a scene of thin, backlit features, both measured against a high-spp
# random-walk reference (the walk is unbiased; diffusion is not, and its error stops falling at its
# bias).
#
#   bench/subsurface_compare.sh FLUENCE OUT_DIR [REF_SPP] [SPP...]
#
# FLUENCE is the fluence binary. For each scene, renders the random-walk reference at REF_SPP
# (default 1024, seed 1; kept if present), then both methods at SPP (default 4 16 64 256, seed 0),
# alternating, at 240 x 180 on 2 threads; appends scene,method,spp,render_s,rmse to
# OUT_DIR/series.csv (RMSE over R, G, B against the reference, by oiiotool --diff).
set -euo pipefail
FLUENCE=$(realpath "$1"); OUT=$2; REF_SPP=${3:-1024}; shift $(( $# < 3 ? $# : 3 ))
SPPS=("$@"); [ ${#SPPS[@]} -gt 0 ] || SPPS=(4 16 64 256)
ROOT=$(realpath "$(dirname "$0")/..")
mkdir -p "$OUT"; OUT=$(realpath "$OUT")

render() {  # render SCENE METHOD SPP SEED OUT.exr -> prints render seconds
    "$FLUENCE" render "$1" --subsurface "$2" --spp "$3" --seed "$4" -r 240 180 -j 2 -o "$5" > "${5%.exr}.log" 2>&1
    sed -n 's/.*render \([0-9.]*\) s.*/\1/p' "${5%.exr}.log"
}
rmse() { oiiotool "$1" --ch R,G,B "$2" --ch R,G,B --diff 2>&1 | sed -n 's/.*RMS error = \([0-9.e+-]*\).*/\1/p'; }

[ -s "$OUT/series.csv" ] || echo "scene,method,spp,render_s,rmse" > "$OUT/series.csv"
for scene in usd_samples/subsurface/subsurface.usda bench/scenes/thin_subsurface.usda; do
    name=$(basename "$scene" .usda)
    ref="$OUT/${name}_ref.exr"
    [ -s "$ref" ] || echo "$name reference (randomwalk, $REF_SPP spp): $(render "$ROOT/$scene" randomwalk "$REF_SPP" 1 "$ref") s"
    for n in "${SPPS[@]}"; do
        for method in randomwalk diffusion; do
            img="$OUT/${name}_${method}_spp$n.exr"
            t=$(render "$ROOT/$scene" "$method" "$n" 0 "$img")
            echo "$name,$method,$n,$t,$(rmse "$img" "$ref")" | tee -a "$OUT/series.csv"
        done
    done
done
