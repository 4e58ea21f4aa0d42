#!/bin/sh
# The denoiser's quality on the benchmark scenes (bench/results/2026-12-05-denoise.md): for each
# scene, a reference at REF_SPP samples, then renders with --denoise at 4, 16 and 64 samples, each
# measured by denoise_quality (relMSE of the denoised and of the noisy beauty, whole image and
# textured region) and timed (the render's and the denoiser's seconds, from its output).
#   bench/denoise_compare.sh BUILD_DIR OUT_DIR [W H [REF_SPP]]
set -eu
build=$1 out=$2 width=${3:-160} height=${4:-120} refSpp=${5:-512}
src=$(cd "$(dirname "$0")/.." && pwd)
fluence=$build/apps/fluence quality=$build/bench/denoise_quality
mkdir -p "$out"
for scene in usd_samples/cornell_box.usda usd_samples/material_ball/material_ball.usda \
             usd_samples/subdivision/creased_cubes.usda usd_samples/smoke/smoke.usda \
             usd_samples/subsurface/subsurface.usda bench/scenes/caustic_glass.usda; do
    name=$(basename "$scene" .usda)
    [ -f "$out/$name.ref.exr" ] ||
        "$fluence" render "$src/$scene" -r "$width" "$height" --spp "$refSpp" --seed 1000 -o "$out/$name.ref.exr" -V0
    images=""
    for spp in 4 16 64; do
        "$fluence" render "$src/$scene" -r "$width" "$height" --spp "$spp" --denoise \
            -o "$out/$name.$spp.exr" -V0 | grep -E "denoised|render [0-9]" | sed "s|^|$name $spp spp: |" || true
        images="$images $out/$name.$spp.exr"
    done
    "$quality" "$out/$name.ref.exr" $images
done
