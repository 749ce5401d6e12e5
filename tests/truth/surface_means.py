#!/usr/bin/python3
"""Per-surface means of linear EXR images, and the noise of two renders (numpy + OpenImageIO).

  /usr/bin/python3 tests/truth/surface_means.py IDS.exr A.exr [B.exr ...] [--erode 1]
      IDS.exr: the id image cycles_reference.py --ids writes (k+1: front of surface k at the
      pixel centre, -(k+1) its back, 0 nothing). For each surface seen from the front, the
      mean RGB of each image over the surface's interior pixels (every pixel within --erode
      pixels of it has the same id), and each image's mean over the first's, per channel.
  /usr/bin/python3 tests/truth/surface_means.py IDS.exr --noise S1.exr S2.exr
      two renders differing only in seed: RMS((s1 - s2) / sqrt 2) / mean over interior pixels
      (luminance Y = 0.2126 R + 0.7152 G + 0.0722 B), the relative noise of one render.

Importable: read_rgb, read_ids, interior, with_luminance, surface_means, relative_noise,
surface_estimates (means with standard errors from seed pairs). Arrays are (rows, columns[,
channels]), the top row first (the EXR's first scanline), float64.
"""
import argparse
import json
import os

import numpy as np
import OpenImageIO as oiio

LUMA = np.array([0.2126, 0.7152, 0.0722])


def _read(path):
    buf = oiio.ImageBuf(path)
    pixels = buf.get_pixels(oiio.FLOAT)
    if buf.has_error or pixels is None or getattr(pixels, "size", 0) == 0:
        raise SystemExit("%s: cannot read the image (%s)" % (path, buf.geterror() or "no pixels"))
    return np.asarray(pixels, dtype=np.float64).reshape(pixels.shape[0], pixels.shape[1], -1), \
        list(buf.spec().channelnames)


def read_rgb(path):
    """(rows, columns, 3): channels R, G, B by name (a grey image's one channel three times)."""
    pixels, names = _read(path)
    picked = [names.index(c) for c in "RGB" if c in names] or [0]
    return pixels[:, :, (picked + picked[-1:] * 3)[:3]]


def read_ids(path):
    """(rows, columns) integers: the first channel of cycles_reference.py's --ids image."""
    return np.rint(_read(path)[0][:, :, 0]).astype(np.int64)


def interior(ids, erode=1):
    """ids where the pixel sees a front face and every pixel within erode has its id, else 0."""
    h, w = ids.shape
    ok = ids > 0
    if erode > 0:
        ok[:erode], ok[h - erode:], ok[:, :erode], ok[:, w - erode:] = False, False, False, False
        padded = np.pad(ids, erode, mode="edge")
        for dj in range(2 * erode + 1):
            for di in range(2 * erode + 1):
                ok &= padded[dj:dj + h, di:di + w] == ids
    return np.where(ok, ids, 0)


def with_luminance(rgb):
    """(..., 4): R, G, B and Y."""
    return np.concatenate([rgb, (rgb @ LUMA)[..., None]], axis=-1)


def surface_means(labels, images):
    """{k: (pixels, [mean RGB of each image])} for every surface k > 0 in labels (interior())."""
    return {k: (int((labels == k).sum()), [img[labels == k].mean(axis=0) for img in images])
            for k in np.unique(labels[labels > 0])}


def relative_noise(labels, s1, s2):
    """(pixels, mean Y, RMS((s1 - s2) / sqrt 2) of Y, their ratio) over the pixels labels > 0."""
    m = labels > 0
    y1, y2 = s1[m] @ LUMA, s2[m] @ LUMA
    mean = 0.5 * (y1.mean() + y2.mean())
    rms = np.sqrt(np.mean((y1 - y2) ** 2 / 2))
    return int(m.sum()), mean, rms, rms / mean


def surface_estimates(labels, pairs):
    """Per surface, the mean of all images of the seed pairs and its standard error.

    pairs: [(s1, s2), ...] RGB images, each pair differing only in seed. Returns {k: (n, mean,
    se, dof)} for each surface k > 0 in labels and k = "all" (every interior pixel), mean and se
    over the channels R, G, B, Y. The pixel noise is independent between pixels (radview's path
    tracer and Cycles both decorrelate pixels), so the variance of the mean over n pixels and
    2P images is mean(sigma_i^2) / (2 P n), with sigma_i^2 = E(s1 - s2)^2 / 2 per pixel: se =
    sqrt(mean over pixels and pairs of ((s1 - s2) / 2)^2 / (P n)), i.e. RMS((s1-s2)/2)/sqrt(n)
    for one pair (RMS about zero, the difference's known mean), with P n degrees of freedom.
    """
    full = [(with_luminance(a), with_luminance(b)) for a, b in pairs]
    out = {}
    for k in [int(k) for k in np.unique(labels[labels > 0])] + ["all"]:
        m = labels > 0 if k == "all" else labels == k
        n = int(m.sum())
        mean = np.mean([img[m].mean(axis=0) for pair in full for img in pair], axis=0)
        d2 = np.mean([((a[m] - b[m]) / 2) ** 2 for a, b in full], axis=(0, 1))
        out[k] = (n, mean, np.sqrt(d2 / (len(full) * n)), len(full) * n)
    return out


def legend(ids_path):
    """{k: label} from IDS.exr.json, if there."""
    if not os.path.isfile(ids_path + ".json"):
        return {}
    with open(ids_path + ".json") as f:
        return {int(k): v for k, v in json.load(f)["ids"].items()}


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("ids")
    p.add_argument("images", nargs="*")
    p.add_argument("--erode", type=int, default=1, help="pixels a surface's pixel must be from its edge (default 1)")
    p.add_argument("--noise", nargs=2, metavar=("S1", "S2"))
    args = p.parse_intermixed_args()
    labels = interior(read_ids(args.ids), args.erode)
    paths = list(args.noise or args.images)
    images = [read_rgb(path) for path in paths]
    for path, img in zip(paths, images):
        if img.shape[:2] != labels.shape:
            raise SystemExit("%s: %dx%d, the id image is %dx%d" % (path, img.shape[1], img.shape[0],
                                                                  labels.shape[1], labels.shape[0]))
    if args.noise:
        print("noise: %d interior pixels, mean Y %.6g, RMS((s1-s2)/sqrt2) %.6g, relative %.4f"
              % relative_noise(labels, *images))
        return
    names = legend(args.ids)
    print("id pixels " + " | ".join("mean R G B of %s" % os.path.basename(a) for a in paths)
          + (" | ratio to the first" if len(images) > 1 else "") + " | surface")
    for k, (n, means) in surface_means(labels, images).items():
        ratios = [" ".join("%.4f" % (m[c] / means[0][c]) if means[0][c] else "-" for c in range(3))
                  for m in means[1:]]
        print("%3d %5d " % (k, n) + " | ".join("%.5g %.5g %.5g" % tuple(m) for m in means)
              + "".join(" | " + r for r in ratios) + " | " + names.get(int(k), ""))


if __name__ == "__main__":
    main()
