#!/usr/bin/env python3
# cycles_stats.py: the numbers of bench/cycles_compare, in plain Python (no numpy).
#
#   cycles_stats.py error IMAGE REFERENCE BANDS
#       RMS of IMAGE - REFERENCE over every pixel of the three channels, and that RMS
#       relative to REFERENCE's mean: "rms_uW relative". IMAGE and REFERENCE are both
#       a trace cube (ENVI .img, float32 BSQ, its .hdr beside it; BANDS = the three
#       0-based cube bands, "k1,k2,k3", radiance converted to uW) or both a
#       cycles_render.py .raw (three float32 planes; BANDS "-").
#   cycles_stats.py ratio TRACE_TRUTH CYCLES_RAW BANDNAMES
#       The mean surface-leaving radiance of trace's converged render, (solar_B +
#       downwelled_B) / transmission_B from its truth cube (trace(1), OUTPUT), over the
#       pixels whose samples all hit, against Cycles' converged image over the same
#       pixels; per channel and over all three ("r1 r2 r3 all", trace / Cycles).
#       BANDNAMES: the three .rad stems, "hawkeye-1,hawkeye-2,hawkeye-3".
#   cycles_stats.py sensor TRACE_CUBE BANDS CYCLES_RAW
#       The same ratio of the images' means over every pixel, at the sensor (trace's
#       path radiance and transmission included): "r1 r2 r3 all".
import array
import math
import re
import sys


def envi_header(img):
    hdr = open(re.sub(r"\.img$", ".hdr", img)).read()
    def value(key):
        m = re.search(r"^\s*" + key + r"\s*=\s*(\{[^}]*\}|[^\n]*)", hdr, re.M | re.I)
        return m.group(1).strip() if m else None
    names = value("band names")
    names = [n.strip() for n in names.strip("{}").split(",")] if names else []
    if value("interleave").lower() != "bsq" or value("data type") != "4" or value("byte order") != "0":
        raise SystemExit("cycles_stats: %s: not a float32 little-endian BSQ cube" % img)
    return int(value("samples")), int(value("lines")), int(value("bands")), names


def planes(path, bands, scale=1.0):
    """The planes `bands` of an ENVI cube (or all three of a .raw when bands is None)."""
    data = array.array("f")
    with open(path, "rb") as f:
        data.frombytes(f.read())
    if sys.byteorder != "little":
        data.byteswap()
    if bands is None:
        n = len(data) // 3
        return [data[i * n:(i + 1) * n] for i in range(3)]
    cols, rows, _, _ = envi_header(path)
    n = cols * rows
    return [array.array("d", (v * scale for v in data[b * n:(b + 1) * n])) for b in bands]


def load(path, spec):
    if spec == "-":
        return planes(path, None)
    return planes(path, [int(b) for b in spec.split(",")], 1e6)  # W -> uW


def error(image, reference, spec):
    a, r = load(image, spec), load(reference, spec)
    total = count = ref_sum = 0.0
    for pa, pr in zip(a, r):
        for x, y in zip(pa, pr):
            total += (x - y) ** 2
            ref_sum += y
            count += 1
    rms = math.sqrt(total / count)
    print("%.6g %.6g" % (rms, rms / (ref_sum / count)))


def ratio(truth, raw, names):
    cols, rows, _, layers = envi_header(truth)
    index = {n: i for i, n in enumerate(layers)}
    cycles = planes(raw, None)
    hit = planes(truth, [index["hit"]])[0]
    out, t_all, c_all = [], 0.0, 0.0
    for ch, name in enumerate(names.split(",")):
        solar, down = planes(truth, [index["solar_" + name], index["downwelled_" + name]], 1e6)
        tau = planes(truth, [index["transmission_" + name]])[0]
        t_sum = c_sum = 0.0
        for i in range(cols * rows):
            if hit[i] == 1 and tau[i] > 0:
                t_sum += (solar[i] + down[i]) / tau[i]
                c_sum += cycles[ch][i]
        out.append(t_sum / c_sum)
        t_all += t_sum
        c_all += c_sum
    print(" ".join("%.4f" % v for v in out + [t_all / c_all]))


def sensor(cube, spec, raw):
    t, c = load(cube, spec), load(raw, "-")
    out = [sum(a) / sum(b) for a, b in zip(t, c)]
    out.append(sum(sum(a) for a in t) / sum(sum(b) for b in c))
    print(" ".join("%.4f" % v for v in out))


if __name__ == "__main__":
    if len(sys.argv) == 5 and sys.argv[1] == "error":
        error(*sys.argv[2:])
    elif len(sys.argv) == 5 and sys.argv[1] == "ratio":
        ratio(*sys.argv[2:])
    elif len(sys.argv) == 5 and sys.argv[1] == "sensor":
        sensor(*sys.argv[2:])
    else:
        raise SystemExit("usage: cycles_stats.py error IMAGE REFERENCE BANDS | "
                         "ratio TRACE_TRUTH CYCLES_RAW BANDNAMES | sensor TRACE_CUBE BANDS CYCLES_RAW")
