"""The denoiser's chart (docs/RESULTS.md, Denoising): from the quality.csv bench/denoise_compare.sh
writes, relMSE against samples per pixel for each scene, denoised (solid) and noisy (dashed), and
beside it the residual bias, the relative difference of the denoised image's mean from the
reference's, with bars of two standard errors (the noisy image's bias, which is zero in
expectation, as hollow markers for scale), on an axis linear within ±0.001 and logarithmic beyond.

    /usr/bin/python3 bench/plot_denoise.py OUT/quality.csv bench/results/figures/2026-12-05-denoise
writes BASE.png and BASE.svg. Points whose relMSE is not positive (the reference's noise larger than
the error left) cannot be drawn on a log axis and are listed on standard output instead.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_rows(path):
    """{scene: [row, ...]} in file order, numbers as floats."""
    scenes = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            scene = row.pop("scene")
            scenes.setdefault(scene, []).append({k: float(v) for k, v in row.items()})
    return scenes


def draw(scenes, out_base):
    fig, (error_ax, bias_ax) = plt.subplots(1, 2, figsize=(11.5, 4.6))
    offsets = {scene: 1.0 + 0.04 * (i - (len(scenes) - 1) / 2) for i, scene in enumerate(scenes)}
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for i, (scene, rows) in enumerate(scenes.items()):
        colour = colours[i % len(colours)]
        for column, style, label in (("relmse_denoised", "-", scene), ("relmse_noisy", "--", None)):
            points = [(r["spp"], r[column]) for r in rows if r[column] > 0]
            for r in rows:
                if r[column] <= 0:
                    print("%s %d spp: %s %.3g not drawn" % (scene, r["spp"], column, r[column]))
            error_ax.loglog([p[0] for p in points], [p[1] for p in points], style, marker="o", color=colour,
                            label=label)
        spp = [r["spp"] * offsets[scene] for r in rows]
        bias_ax.errorbar(spp, [r["bias_denoised"] for r in rows],
                         yerr=[2 * r["bias_standard_error"] for r in rows], marker="o", color=colour,
                         capsize=3, label=scene)
        bias_ax.plot(spp, [r["bias_noisy"] for r in rows], linestyle="none", marker="o", markerfacecolor="none",
                     color=colour)
    error_ax.set_xlabel("samples per pixel")
    error_ax.set_ylabel("relMSE against the reference")
    error_ax.set_title("denoised (solid) and noisy (dashed)")
    error_ax.grid(True, which="both", alpha=0.3)
    error_ax.legend(fontsize="small")
    bias_ax.set_xscale("log")
    # Linear within ±0.001 and logarithmic beyond, so a bias of 0.1 and one of 0.001 both show.
    bias_ax.set_yscale("symlog", linthresh=1e-3)
    bias_ax.axhline(0.0, color="black", linewidth=0.8)
    bias_ax.set_xlabel("samples per pixel")
    bias_ax.set_ylabel("(image mean - reference mean) / reference mean")
    bias_ax.set_title("residual bias, ±2 s.e. (hollow: noisy image)")
    bias_ax.grid(True, which="both", alpha=0.3)
    for ax in (error_ax, bias_ax):
        ax.set_xticks([4, 16, 64])
        ax.set_xticklabels(["4", "16", "64"])
    fig.tight_layout()
    for ext in ("png", "svg"):
        fig.savefig("%s.%s" % (out_base, ext), dpi=110)
    plt.close(fig)


def main():
    if len(sys.argv) != 3:
        raise SystemExit("usage: plot_denoise.py QUALITY.csv OUT_BASE")
    draw(read_rows(sys.argv[1]), sys.argv[2])


if __name__ == "__main__":
    main()
