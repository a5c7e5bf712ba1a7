# Writes the TAPE7 LOWTRAN 7 would write for one deck (.tp5, one run, as
# build_radiance --write-decks writes them), with made-up constant values instead of
# LOWTRAN's physics, so that tests know every number of the .rad it gives:
#   awk -v T=0.8 -v ES=5e-6 -v LP=1e-7 -v LS=2e-7 -f fake_lowtran7.awk DECK > TAPE7
# T transmittance of every path; ES solar irradiance above the atmosphere, W cm-2
# (cm-1)-1 (IEMSCT 3); LP solar path radiance of paths that end at the ground (views),
# LS that of paths to space (sky), W cm-2 sr-1 (cm-1)-1. The thermal terms are 0
# (TBOUND 0 echoed). Layout: LOWTRAN 7 rev 4.2, MAIN (card echo, statements 560 on)
# and TRANS (FORMAT 931-933 headings, 907/917/927/937 rows, ' -9999.'); man tape7(5).
{ deck[NR] = $0 }
END {
    card1 = deck[1]; model = substr(card1, 1, 5) + 0; iemsct = substr(card1, 11, 5) + 0
    im = substr(card1, 56, 5) + 0
    k = 3; ml = "    0"
    if ((model == 0 || model == 7) && im == 1) {
        ml = deck[3]; layers = substr(ml, 1, 5) + 0
        per = 1 + 2 * (substr(ml, 6, 5) + 0) + (substr(ml, 11, 5) + 0)
        k = 4 + layers * per
    }
    card3 = deck[k++]
    a1 = "    0    0    0    0"; a2 = sprintf("%10.3f%10.3f%10.3f%10.3f%10.3f%10.3f%10.3f%10.3f", 0, 0, 0, 0, 0, 0, 0, 0)
    if (iemsct == 2) { a1 = deck[k++]; a2 = deck[k++] }
    card4 = deck[k]
    v1 = substr(card4, 1, 10) + 0; v2 = substr(card4, 11, 10) + 0; dv = substr(card4, 21, 10) + 0
    h2 = substr(card3, 11, 10) + 0; angle = substr(card3, 21, 10) + 0
    print substr(card1, 1, 65) sprintf("%8.3f%7.2f", 0, 0)
    print deck[2]
    printf "%10.3f%10.3f%10.3f%10d\n", 0, 0, 0, 0
    printf "%10.3f%10.3f%10.3f\n", 0, 0, 0
    print ml
    printf "%10.3f%10.3f%10.3f%10.3f%10.3f%10.3f%5d\n", substr(card3, 1, 10), h2, angle, 0, 0, 0, 0
    print a1
    print a2
    print card4
    print "    0"
    if (iemsct == 3) print "  FREQ   TRANS     SOL TR  SOLAR    "
    else print "  FREQ   TRANS     ATMOS   PATH     SINGLE   GROUND DIRECT   TOTAL RAD"
    depth = -log(T)
    lp = angle > 90 ? LP : LS
    for (v = v1; v <= v2 + dv / 2; v += dv) {
        if (iemsct == 3)
            line = sprintf("%6.0f.%8.4f%9.2E%9.2E", v, T, ES * T, ES)
        else
            line = sprintf("%6.0f.%8.4f%9.2E%9.2E%9.2E%9.2E%9.2E%9.2E%8.4f%8.4f", v, T, 0, lp, lp, 0, 0, lp, T, T)
        printf "%-95s%10.3E\n", line, depth
    }
    print " -9999."
}
