# nofit_table.awk: out/nofit/validation.txt from the per-render statistics (nofit_stats.awk)
# and scores (landsat_scene score) of make nofit. Arguments: files named
# OUT/DATE/GAIN/stats.txt and OUT/DATE/GAIN/score.txt (GAIN: H, or L = band 4 at low gain).
# Bands are reported by ETM+ number (1, 2, 3, 4, 5, 7); bands other than 4 are the same in
# both gain renders and are reported once (gain H). OUT/evidence/KIND/H/stats.txt: the
# evidence renders at the date picture_date (-v picture_date=MMDD).
BEGIN {
    etm[1] = 1; etm[2] = 2; etm[3] = 3; etm[4] = 4; etm[5] = 5; etm[6] = 7
    print "# kind scope etm_band gain date n obs_median obs_p05 obs_p95 pred_median" \
        " pred_low pred_high diff inside obs_n255 pred_n255 roc rms"
    print "# kind dn: DN over the scope's pixels at one date; pred_low/high = the predicted" \
        " p05/p95; diff = obs_median - pred_median; inside = 1 if |diff| <= 1 DN"
    print "# kind band: date all; pred_low/high = the lowest/highest predicted median over" \
        " the dates; diff = obs_median minus the nearest end (0 inside);" \
        " inside = 1 if obs_median is within [pred_low - 1, pred_high + 1]"
    print "# kind adjacency, dark: as dn, for the evidence renders at one date (high gain):" \
        " with trace's adjacency effect; with every reflectance 0 (path radiance alone)"
    print "# kind points: scope points_held (olinda_held.cpt), n points; roc = rank-order" \
        " correlation, rms = RMS difference (DN) of predicted and observed; other columns -"
}
function render(f,    p, m) {
    m = split(f, p, "/")
    date = p[m - 2]; gain = p[m - 1]; kind = "dn"
    if (m >= 4 && p[m - 3] == "evidence") { kind = date; date = picture_date }
}
FNR == 1 { render(FILENAME) }
FILENAME ~ /stats[.]txt$/ {
    if ($2 != 4 && gain != "H") next
    d = $4 - $7
    if (kind != "dn") {
        printf "%s %s %d %s %s %d %d %d %d %d %d %d %d %d %d %d - -\n", kind, $1, etm[$2], \
            gain, date, $3, $4, $5, $6, $7, $8, $9, d, (d <= 1 && d >= -1), $10, $11
        next
    }
    key = $1 SUBSEP $2 SUBSEP gain
    if (!(key in seen)) { seen[key] = 1; order[++nk] = key; obs[key] = $4 " " $5 " " $6
        nn[key] = $3; o255[key] = $10; lo[key] = 999; hi[key] = -1; med[key] = $4 }
    printf "dn %s %d %s %s %d %d %d %d %d %d %d %d %d %d %d - -\n", $1, etm[$2], gain, date, \
        $3, $4, $5, $6, $7, $8, $9, d, (d <= 1 && d >= -1), $10, $11
    if ($7 < lo[key]) lo[key] = $7
    if ($7 > hi[key]) hi[key] = $7
    next
}
FILENAME ~ /score[.]txt$/ && $1 == "points" {
    if ($2 != 4 && gain != "H") next
    printf "points points_held %d %s %s %d - - - - - - - - - - %s %s\n", etm[$2], gain, \
        date, $3, $4, $5
}
END {
    for (k = 1; k <= nk; k++) {
        split(order[k], f, SUBSEP)
        o = med[order[k]]
        d = o < lo[order[k]] ? o - lo[order[k]] : (o > hi[order[k]] ? o - hi[order[k]] : 0)
        printf "band %s %d %s all %d %s - %d %d %d %d %d - - -\n", f[1], etm[f[2]], f[3], \
            nn[order[k]], obs[order[k]], lo[order[k]], hi[order[k]], d, \
            (o >= lo[order[k]] - 1 && o <= hi[order[k]] + 1), o255[order[k]]
    }
}
