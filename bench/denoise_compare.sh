#!/bin/sh
# The denoiser's quality on the benchmark scenes (bench/results/2026-12-05-denoise-3.md): for each
# scene, a reference at REF_SPP samples (with --denoise-buffers, so its variance is known), then
# renders with --denoise at 4, 16 and 64 samples, each measured by denoise_quality (relMSE of the
# denoised and of the noisy beauty, whole image and textured region, and the bias of their means)
# and timed (the render's and the denoiser's seconds, from its output). Writes OUT_DIR/quality.csv
# (scene, spp, then denoise_quality's columns), which bench/plot_denoise.py charts.
#   bench/denoise_compare.sh BUILD_DIR OUT_DIR [W H [REF_SPP]]
#   DENOISE_SCENES="usd_samples/hair/hair.usda ..." bench/denoise_compare.sh ...   other scenes
set -eu
build=$1 out=$2 width=${3:-160} height=${4:-120} refSpp=${5:-512}
src=$(cd "$(dirname "$0")/.." && pwd)
fluence=$build/apps/fluence quality=$build/bench/denoise_quality
scenes=${DENOISE_SCENES:-"usd_samples/cornell_box.usda usd_samples/material_ball/material_ball.usda
    usd_samples/subdivision/creased_cubes.usda usd_samples/smoke/smoke.usda
    usd_samples/subsurface/subsurface.usda bench/scenes/caustic_glass.usda"}
mkdir -p "$out"
csv=$out/quality.csv
echo "scene,spp,relmse_denoised,relmse_noisy,relmse_textured_denoised,relmse_textured_noisy,ref_noise,bias_denoised,bias_noisy,bias_standard_error" >"$csv"
for scene in $scenes; do
    name=$(basename "$scene" .usda)
    [ -f "$out/$name.ref.exr" ] ||
        "$fluence" render "$src/$scene" -r "$width" "$height" --spp "$refSpp" --seed 1000 --denoise-buffers \
            -o "$out/$name.ref.exr" -V0
    images=""
    for spp in 4 16 64; do
        "$fluence" render "$src/$scene" -r "$width" "$height" --spp "$spp" --denoise \
            -o "$out/$name.$spp.exr" -V0 | grep -E "denoised|render [0-9]" | sed "s|^|$name $spp spp: |" || true
        images="$images $out/$name.$spp.exr"
    done
    # shellcheck disable=SC2086
    "$quality" "$out/$name.ref.exr" $images | tail -n +2 |
        sed -E "s|^[^,]*/$name\.([0-9]+)\.exr,|$name,\1,|" >>"$csv"
done
column -s, -t "$csv"
