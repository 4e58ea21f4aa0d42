#!/usr/bin/env bash
# Fluence beside Cycles on one of the Cycles peer's scenes (shared/peers/cycles): `smoke` (scene b:
# the same VDB, lights, camera and 256 x 256 box-filtered pixels) or `sss` (scene c: the same cage
# at subdivision level 4, light, floor and camera; bench/peer_scenes/cycles_SCENE.usda says how
# close each is).
#
#   bench/peer_compare.sh SCENE FLUENCE PEER_DIR OUT_DIR [REF_SPP] [SPP...]
#
# FLUENCE is the fluence binary; PEER_DIR a writable copy of shared/peers/cycles (scenes.py,
# compare.py); OUT_DIR receives the images and `series.csv`. Each renderer first renders its own
# reference at REF_SPP (default 2048, seed 1; kept if present), then the series at SPP (default
# 4 16 64 256, seed 0), the two renderers alternating at each sample count so that the machine's
# load falls on both alike. Every image's RMSE is measured against both references, with the
# peer's compare.py. Needs blender, /usr/bin/python3 with numpy and OpenImageIO (peer README).
# Times: Fluence's is its own "render" time (after the scene is built); Cycles' is the
# render_time it writes into the EXR header (after its scene sync); both on 2 threads.
set -euo pipefail
NAME=$1; FLUENCE=$(realpath "$2"); PEER=$(realpath "$3"); OUT=$4; REF_SPP=${5:-2048}; shift $(( $# < 5 ? $# : 5 ))
SPPS=("$@"); [ ${#SPPS[@]} -gt 0 ] || SPPS=(4 16 64 256)
SCENE=$(realpath "$(dirname "$0")/peer_scenes/cycles_$NAME.usda")
case "$NAME" in
    smoke) EXTRA=() ;;
    sss) EXTRA=(--subdiv-level 4) ;;  # Cycles' render level
    *) echo "unknown peer scene '$NAME' (smoke or sss)" >&2; exit 2 ;;
esac
PY=/usr/bin/python3
mkdir -p "$OUT"; OUT=$(realpath "$OUT")

cycles() {  # cycles SPP SEED OUT.exr -> prints render seconds
    (cd "$PEER" && blender -b --factory-startup -P scenes.py -- --scene "$NAME" --spp "$1" --seed "$2" --out "$3" \
        --res 256 256 --threads 2 > "${3%.exr}.log" 2>&1)
    "$PY" "$PEER/compare.py" stats --json "$3" | "$PY" -c "import json,sys; print('%.3f' % json.load(sys.stdin)['times']['render_time'])"
}
fluence() {  # fluence SPP SEED OUT.exr -> prints render seconds
    "$FLUENCE" render "$SCENE" "${EXTRA[@]}" --spp "$1" --seed "$2" -j 2 -o "$3" > "${3%.exr}.log" 2>&1
    sed -n 's/.*render \([0-9.]*\) s.*/\1/p' "${3%.exr}.log"
}
rmse() { "$PY" "$PEER/compare.py" diff --json "$1" "$2" | "$PY" -c "import json,sys; print('%.6g' % json.load(sys.stdin)['rmse'])"; }

[ -s "$OUT/cycles_ref.exr" ] || echo "cycles reference: $(cycles "$REF_SPP" 1 "$OUT/cycles_ref.exr") s"
[ -s "$OUT/fluence_ref.exr" ] || echo "fluence reference: $(fluence "$REF_SPP" 1 "$OUT/fluence_ref.exr") s"
echo "references, fluence against cycles:"
"$PY" "$PEER/compare.py" diff "$OUT/fluence_ref.exr" "$OUT/cycles_ref.exr"

echo "renderer,spp,render_s,rmse_vs_own_ref,rmse_vs_cycles_ref,rmse_vs_fluence_ref" > "$OUT/series.csv"
for n in "${SPPS[@]}"; do
    for r in cycles fluence; do
        img="$OUT/${r}_spp$n.exr"
        t=$($r "$n" 0 "$img")
        own=$(rmse "$img" "$OUT/${r}_ref.exr")
        echo "$r,$n,$t,$own,$(rmse "$img" "$OUT/cycles_ref.exr"),$(rmse "$img" "$OUT/fluence_ref.exr")" | tee -a "$OUT/series.csv"
    done
done
