#!/usr/bin/env bash
# Guided against classic random-walk subsurface (issue #25 item 3): relMSE per sample and per CPU
# second on the subsurface sample and on the Cycles peer's matched scene (`scenes.py --sss-mfp`,
# bench/peer_scenes/cycles_sss.usda), against a classic-walk reference rendered as two halves.
#
#   bench/subsurface_guided.sh FLUENCE OUT_DIR [REF_SPP] [SPP] [SEEDS]
#
# For each scene: the reference is two classic renders of REF_SPP/2 samples (seeds 1001, 1002;
# kept if present), R = (A + B) / 2, whose own noise (A - B)^2 / 4 is subtracted from every error
# (bench/fluence_bench/metrics.py explains the estimate). Then classic and guided alternate at SPP
# samples (default 64) for seeds 1..SEEDS (default 3), on 2 threads; each render's CPU time is its
# user + system time (/usr/bin/time). Appends scene,method,spp,seed,cpu_s,relmse,bias_r,bias_g,bias_b
# to OUT_DIR/series.csv (relmse over R, G, B with eps 0.01; bias: the relative difference of the
# channel means against the reference). Averages are read from oiiotool --printstats, scaled by
# 1000 first so that its six decimals keep the small errors.
set -euo pipefail
FLUENCE=$(realpath "$1"); OUT=$2; REF_SPP=${3:-1024}; SPP=${4:-64}; SEEDS=${5:-3}
ROOT=$(realpath "$(dirname "$0")/..")
mkdir -p "$OUT"; OUT=$(realpath "$OUT")

render() {  # render NAME METHOD SPP SEED OUT.exr -> prints CPU seconds
    local args
    case $1 in
        subsurface) args=("$ROOT/usd_samples/subsurface/subsurface.usda" -r 160 120) ;;
        peer_sss) args=("$ROOT/bench/peer_scenes/cycles_sss.usda" -r 128 128 --subdiv-level 4) ;;
    esac
    /usr/bin/time -f '%U %S' -o "$5.time" "$FLUENCE" render "${args[@]}" --integrator path --subsurface "$2" \
        --spp "$3" --seed "$4" -j 2 -o "$5" > "${5%.exr}.log" 2>&1
    awk '{ printf "%.2f", $1 + $2 }' "$5.time"
}
averages() { sed -n 's/.*Stats Avg: *\([-0-9.e+]*\) *\([-0-9.e+]*\) *\([-0-9.e+]*\).*/\1 \2 \3/p' | head -1; }

[ -s "$OUT/series.csv" ] || echo "scene,method,spp,seed,cpu_s,relmse,bias_r,bias_g,bias_b" > "$OUT/series.csv"
for name in subsurface peer_sss; do
    a="$OUT/${name}_ref_a.exr"; b="$OUT/${name}_ref_b.exr"
    [ -s "$a" ] || echo "$name reference half A: $(render "$name" randomwalk $((REF_SPP / 2)) 1001 "$a") CPU s"
    [ -s "$b" ] || echo "$name reference half B: $(render "$name" randomwalk $((REF_SPP / 2)) 1002 "$b") CPU s"
    oiiotool "$a" --ch R,G,B "$b" --ch R,G,B --add --mulc 0.5 -d float -o "$OUT/${name}_ref.exr"
    oiiotool "$a" --ch R,G,B "$b" --ch R,G,B --sub --dup --mul --mulc 0.25 -d float -o "$OUT/${name}_ref_var.exr"
    oiiotool "$OUT/${name}_ref.exr" --dup --mul --addc 0.01 -d float -o "$OUT/${name}_ref_den.exr"
    read -r mr mg mb < <(oiiotool "$OUT/${name}_ref.exr" --printstats 2>&1 | averages)
    read -r nr ng nb < <(oiiotool "$OUT/${name}_ref_var.exr" "$OUT/${name}_ref_den.exr" --div --mulc 1000 --printstats 2>&1 | averages)
    echo "$name reference: mean $mr $mg $mb, own relMSE $(echo "$nr $ng $nb" | awk '{ print ($1 + $2 + $3) / 3000 }')"
    for seed in $(seq 1 "$SEEDS"); do
        for method in randomwalk randomwalk_guided; do
            img="$OUT/${name}_${method}_spp${SPP}_seed$seed.exr"
            cpu=$(render "$name" "$method" "$SPP" "$seed" "$img")
            read -r er eg eb < <(oiiotool "$img" --ch R,G,B "$OUT/${name}_ref.exr" --sub --dup --mul \
                "$OUT/${name}_ref_var.exr" --sub "$OUT/${name}_ref_den.exr" --div --mulc 1000 --printstats 2>&1 | averages)
            read -r dr dg db < <(oiiotool "$img" --ch R,G,B "$OUT/${name}_ref.exr" --sub --mulc 1000 --printstats 2>&1 | averages)
            echo "$name,$method,$SPP,$seed,$cpu,$(echo "$er $eg $eb" | awk '{ print ($1 + $2 + $3) / 3000 }'),$(
                echo "$dr $dg $db $mr $mg $mb" | awk '{ printf "%.5f,%.5f,%.5f", $1 / $4 / 1000, $2 / $5 / 1000, $3 / $6 / 1000 }')" |
                tee -a "$OUT/series.csv"
        done
    done
done
