#!/usr/bin/env bash
# Each solution method against a common reference: error against time (issue #9's figures).
#
#   bench/integrator_compare.sh FLUENCE SCENE OUT_DIR REF_INTEGRATOR REF_SPP "INTEGRATORS" [SPP...]
#
# Renders SCENE (a .usda, at its own resolution or at RES="W H" from the environment, 2 threads) once with REF_INTEGRATOR at REF_SPP
# (seed 1; kept if present) as the reference, then every integrator in the space-separated list
# at each SPP (default 4 16 64 256, seed 0), the integrators taking turns at each sample count so
# that the machine's load falls on all alike; appends scene,integrator,spp,render_s,rmse to
# OUT_DIR/series.csv (RMSE over R, G, B against the reference, by oiiotool --diff). A method that
# misses light the scene has (its path classes) stops converging at that missing light: the chart
# shows it flatten.
set -euo pipefail
FLUENCE=$(realpath "$1"); SCENE=$(realpath "$2"); OUT=$3; REF_INTEGRATOR=$4; REF_SPP=$5; INTEGRATORS=($6)
shift 6
SPPS=("$@"); [ ${#SPPS[@]} -gt 0 ] || SPPS=(4 16 64 256)
mkdir -p "$OUT"; OUT=$(realpath "$OUT")
NAME=$(basename "$SCENE" .usda)

render() {  # render INTEGRATOR SPP SEED OUT.exr -> prints render seconds
    "$FLUENCE" render "$SCENE" ${RES:+-r $RES} --integrator "$1" --spp "$2" --seed "$3" -j 2 -o "$4" > "${4%.exr}.log" 2>&1
    sed -n 's/.*render \([0-9.]*\) s.*/\1/p' "${4%.exr}.log"
}
rmse() { oiiotool "$1" --ch R,G,B "$2" --ch R,G,B --diff 2>&1 | sed -n 's/.*RMS error = \([0-9.e+-]*\).*/\1/p'; }

ref="$OUT/${NAME}_ref_${REF_INTEGRATOR}.exr"
[ -s "$ref" ] || echo "$NAME reference ($REF_INTEGRATOR, $REF_SPP spp): $(render "$REF_INTEGRATOR" "$REF_SPP" 1 "$ref") s"
[ -s "$OUT/series.csv" ] || echo "scene,integrator,spp,render_s,rmse" > "$OUT/series.csv"
for n in "${SPPS[@]}"; do
    for integrator in "${INTEGRATORS[@]}"; do
        img="$OUT/${NAME}_${integrator}_spp$n.exr"
        t=$(render "$integrator" "$n" 0 "$img")
        echo "$NAME,$integrator,$n,$t,$(rmse "$img" "$ref")" | tee -a "$OUT/series.csv"
    done
done
