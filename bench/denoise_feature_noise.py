"""Where the denoiser's guides are noisy (depth of field, motion blur, hair: a pixel's first hits
differ from sample to sample), does it lose quality? For each image rendered with --denoise, the
pixels are split by how far its albedo and normal AOVs (a few samples' means) are from the
reference's (many samples': nearly their expectation): |albedo - albedo_ref| + |N - N_ref|, summed
over the components, above THRESHOLD (default 0.1) marks a pixel whose features are noisy. Prints
the share of such pixels and, in each part, the relMSE of the denoised and of the noisy beauty
against the reference (as bench/denoise_quality measures it) and their ratio, the gain.

    /usr/bin/python3 bench/denoise_feature_noise.py REF.exr IMAGE.exr... [--threshold 0.1]
Results: bench/results/2026-12-05-denoise-3.md.
"""
import argparse

import numpy as np
import OpenImageIO as oiio


def load(path):
    image = oiio.ImageInput.open(path)
    if image is None:
        raise SystemExit("cannot read " + path)
    spec = image.spec()
    pixels = image.read_image(oiio.FLOAT).reshape(spec.height, spec.width, spec.nchannels)
    image.close()
    return {name: pixels[:, :, c] for c, name in enumerate(spec.channelnames)}


def stack(image, names):
    return np.stack([image[n] for n in names])


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("reference")
    parser.add_argument("images", nargs="+")
    parser.add_argument("--threshold", type=float, default=0.1)
    args = parser.parse_args()
    ref = load(args.reference)
    truth = stack(ref, "RGB")
    weight = truth**2 + 0.01
    features = ["albedo.R", "albedo.G", "albedo.B", "N.X", "N.Y", "N.Z"]
    print("image,noisy_feature_share,gain_noisy_features,gain_clean_features,"
          "relmse_denoised_noisy_features,relmse_noisy_noisy_features,relmse_denoised_clean,relmse_noisy_clean")
    for path in args.images:
        image = load(path)
        distance = np.abs(stack(image, features) - stack(ref, features)).sum(axis=0)
        noisy_features = distance > args.threshold
        row = [path, "%.3f" % noisy_features.mean()]
        errors = []
        for part in (noisy_features, ~noisy_features):
            for names in ("RGB", ["noisy.R", "noisy.G", "noisy.B"]):
                error = (stack(image, names) - truth) ** 2 / weight
                errors.append(error[:, part].mean() if part.any() else float("nan"))
        row += ["%.2f" % (errors[1] / errors[0]), "%.2f" % (errors[3] / errors[2])]
        row += ["%.4g" % e for e in errors]
        print(",".join(row))


if __name__ == "__main__":
    main()
