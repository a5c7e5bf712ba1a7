# nofit_water_ems.awk: water.ems (ems(5), layout 2) for olinda_nofit.mat from a spectrum
# file "wavelength_um reflectance" (the water-leaving reflectance): curve 0 = 2 x that
# reflectance (the diffuse part, weighted 1 - SPECULARITY = 0.5 by trace), curve 1 = 2 x the
# Fresnel reflectance F of the sea surface at normal incidence (the mirror ray, weighted
# SPECULARITY = 0.5). Usage: awk -v fresnel=F -f nofit_water_ems.awk SPECTRUM > water.ems
BEGIN {
    print "# water: curve 0 = 1 - 2 x water-leaving reflectance (" ARGV[1] "),"
    print "# curve 1 = 1 - 2 x " fresnel " (Fresnel, normal incidence); no fall-off"
    print 2
    for (i = 0; i <= 90; i++) print 1
    print "CURVE_BEGIN"
}
!/^[ \t]*(#|$)/ { printf "%s %.6f\n", $1, 1 - 2 * $2 }
END {
    print "CURVE_END"
    print "CURVE_BEGIN"
    printf "0.3 %.6f\n2.6 %.6f\n", 1 - 2 * fresnel, 1 - 2 * fresnel
    print "CURVE_END"
}
