# nofit_stats.awk: DN statistics of one render against L7_ETMs.tif, per group of pixels.
# Input, one line per pixel (paste of od dumps): ocean flag, class (classes_image.tif),
# the 6 observed DNs, the 6 predicted DNs. Groups: "ocean" (the DEM's sea mask) and
# "class:NAME" for classes 1-4. Output rows "scope band n obs_median obs_p05 obs_p95
# pred_median pred_p05 pred_p95 obs_n255 pred_n255" (quantiles from the 0-255 histograms:
# the smallest DN whose cumulative count reaches the fraction; n255: pixels at 255).
BEGIN { name[1] = "water"; name[2] = "vegetation"; name[3] = "urban"; name[4] = "sand" }
function add(g, i) {
    n[g]++
    for (b = 1; b <= 6; b++) { ho[g, b, $(2 + b)]++; hp[g, b, $(8 + b)]++ }
}
function q(h, g, b, f,    c, v) {
    c = 0
    for (v = 0; v <= 255; v++) { c += h[g, b, v]; if (c >= f * n[g]) return v }
    return 255
}
NF == 14 { if ($1 != 0) add("ocean"); if ($2 in name) add("class:" name[$2]) }
END {
    ng = split("ocean class:water class:vegetation class:urban class:sand", groups, " ")
    for (k = 1; k <= ng; k++) {
        g = groups[k]
        if (!(g in n)) continue
        for (b = 1; b <= 6; b++)
            print g, b, n[g], q(ho, g, b, 0.5), q(ho, g, b, 0.05), q(ho, g, b, 0.95), \
                q(hp, g, b, 0.5), q(hp, g, b, 0.05), q(hp, g, b, 0.95), \
                ho[g, b, 255] + 0, hp[g, b, 255] + 0
    }
}
