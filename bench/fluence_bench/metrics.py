"""Error of an image against a reference rendered as two independent halves.

The reference is the mean R = (A + B) / 2 of two renders with different seeds, each at half the
reference's samples. Its own noise is known per pixel: A - B has variance 2 s^2 where s^2 is the
variance of one half, so (A - B)^2 / 4 estimates Var(R) = s^2 / 2 without bias. Since the test
image X is independent of R, E[(X - R)^2] = E[(X - mu)^2] + Var(R), and

    relMSE = mean over pixels and channels of [ (X - R)^2 - (A - B)^2 / 4 ] / (R^2 + eps)

estimates X's own relative MSE against the true image mu (eps = 1e-2, as in the Cycles peer's
compare.py, keeps black pixels from dominating). It may come out slightly negative when X is as
good as the reference. ref_relmse, the mean of (A - B)^2 / 4 / (R^2 + eps), is the reference's own
noise level, the amount subtracted.

MARE (mean absolute relative error) is mean |X - R| / (R + eps). It cannot be corrected the same
way; ref_mare, mean |A - B| / 2 / (R + eps), is the reference's own mean absolute deviation (for
Gaussian noise |A - B| / 2 has the same mean as |R - mu|), so a MARE near ref_mare is at the
reference's noise.

Bias: the relative difference of the image means, sum(X - R) / sum(R), with its standard error
from the spread of the per-pixel differences (pixels taken as independent, which holds for
per-pixel Monte Carlo and is optimistic for sppm and radiosity, whose pixels share photons and
patches); `bias_significant` is |bias| > 3 standard errors.
"""
import numpy as np

REL_EPS = 1e-2
BIAS_SIGMAS = 3.0


def read_rgb(path):
    import OpenImageIO as oiio
    pixels = oiio.ImageBuf(str(path)).get_pixels(oiio.FLOAT)
    return np.asarray(pixels, dtype=np.float64)[:, :, :3]


class Reference:
    def __init__(self, half_a, half_b, spp):
        a, b = read_rgb(half_a), read_rgb(half_b)
        self.spp = spp
        self.mean = (a + b) / 2
        self.variance = (a - b) ** 2 / 4
        self.abs_deviation = np.abs(a - b) / 2

    def noise(self):
        return {"ref_spp": self.spp, "ref_relmse": float(np.mean(self.variance / (self.mean ** 2 + REL_EPS))),
                "ref_mare": float(np.mean(self.abs_deviation / (self.mean + REL_EPS)))}

    def error(self, image_path):
        x = read_rgb(image_path)
        nonfinite = int(np.count_nonzero(~np.isfinite(x)))
        x = np.where(np.isfinite(x), x, 0.0)
        d = x - self.mean
        pixel_diff = d.sum(axis=2).ravel()
        total = self.mean.sum()
        bias = pixel_diff.sum() / total
        bias_se = np.sqrt(pixel_diff.size) * pixel_diff.std() / total
        return {"relmse": float(np.mean((d ** 2 - self.variance) / (self.mean ** 2 + REL_EPS))),
                "relmse_uncorrected": float(np.mean(d ** 2 / (self.mean ** 2 + REL_EPS))),
                "mare": float(np.mean(np.abs(d) / (self.mean + REL_EPS))),
                "bias": float(bias), "bias_se": float(bias_se),
                "bias_significant": bool(abs(bias) > BIAS_SIGMAS * bias_se),
                "nonfinite_pixels": nonfinite, **self.noise()}

    def agreement(self, other):
        """How far this reference lies from OTHER (another renderer's reference of the same scene),
        both references' own noise taken out: relMSE is the mean of [(R - O)^2 - Var(R) - Var(O)] /
        (O^2 + eps), the squared difference the two scenes (not the noise) leave; `bias` per channel
        is the relative difference of the image means, sum(R - O) / sum(O), and `bias_se` its
        standard error from the two references' per-pixel variances."""
        d = self.mean - other.mean
        relmse = np.mean((d ** 2 - self.variance - other.variance) / (other.mean ** 2 + REL_EPS))
        totals = other.mean.sum(axis=(0, 1))
        bias = d.sum(axis=(0, 1)) / totals
        bias_se = np.sqrt((self.variance + other.variance).sum(axis=(0, 1))) / totals
        return {"relmse": float(relmse), "bias": [float(b) for b in bias], "bias_se": [float(s) for s in bias_se]}


def fitted_slope(xs, ys):
    """Least-squares slope of log y against log x over the positive points (nan with fewer than 2)."""
    points = [(np.log(x), np.log(y)) for x, y in zip(xs, ys) if x > 0 and y > 0]
    if len(points) < 2:
        return float("nan")
    lx, ly = np.array(points).T
    if np.ptp(lx) == 0:
        return float("nan")
    return float(np.polyfit(lx, ly, 1)[0])


def time_to_error(times, errors, target):
    """Seconds at which the error first reaches TARGET, interpolated log-log between rungs (nan if never)."""
    pts = sorted((t, e) for t, e in zip(times, errors) if t > 0 and e > 0)
    for (t0, e0), (t1, e1) in zip(pts, pts[1:]):
        if e0 <= target:
            return t0
        if e1 <= target:
            f = (np.log(target) - np.log(e0)) / (np.log(e1) - np.log(e0))
            return float(np.exp(np.log(t0) + f * (np.log(t1) - np.log(t0))))
    return pts[0][0] if pts and pts[0][1] <= target else float("nan")
