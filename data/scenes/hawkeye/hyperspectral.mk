# hyperspectral.mk: the hawkeye scene seen by an imaging spectrometer (VIEW=hyperspectral,
# or `make hyperspectral`; included by the Makefile before pipelines/scene.mk). A pushbroom
# (hyperspectral.adv) of 211 bands, 0.4-2.5 um every 10 nm (hyperspectral.bands: an
# AVIRIS-like set, not AVIRIS's table), into out/hyperspectral/:
#   hyperspectral.snd    hawkeye.snd's sensor height, date and place with the table's bands,
#                        5 spectral samples each, centre - FWHM to centre + FWHM
#   sen/band-K.sen       band K's Gaussian response at those samples (gain 1, bias 0)
#   hyperspectral.mat    hawkeye.mat with 0.35-2.6 um spectra for grass, water, asphalt,
#                        concrete and the tree canopy (vswir/*.ems, from data/spectra)
#   hawkeye.img/.hdr     trace's cube: 1055 spectral samples (ENVI, their wavelengths)
#   hawkeye.tif          the band radiance of the 211 bands (sensorize --float: float32,
#                        W cm-2 sr-1 um-1, each band's centre wavelength and FWHM), as an
#                        imaging spectrometer's radiance product; hawkeye.png its preview
HSI_TABLE  = hyperspectral.bands
# data/spectra of the repository this folder is in (SPECTRA=DIR for a copy elsewhere).
ifndef SPECTRA
SPECTRA    := $(abspath $(dir $(lastword $(MAKEFILE_LIST)))../../spectra)
endif
BANDS      := $(shell awk '!/^[ \t]*(\#|$$)/ { n++ } END { print n + 0 }' $(HSI_TABLE))
SND        = $(OUT)/hyperspectral.snd
SENS       = $(foreach k,$(shell seq 1 $(BANDS)),$(OUT)/sen/band-$(k).sen)
SCENE_MAT  = $(OUT)/hyperspectral.mat
# Band radiance, not counts: a spectrometer's radiance product (sensorize(1) --float).
SENSORIZE  = $(SIGCHAIN_BIN)/sensorize --float
# Materials given a spectrum over the spectrometer's range (the others keep their
# visible curves, which trace holds constant past 0.75 um): MATERIAL_FILE=SOURCE.
HSI_SPECTRA = fall_grass.ems=ecostress_grass water.ems=water_case1_chl03 \
  asphalt.ems=ecostress_construction_asphalt concrete.ems=ecostress_concrete_runway \
  canopy.ems=ecostress_deciduous
HSI_EMS    = $(foreach m,$(HSI_SPECTRA),$(OUT)/vswir/$(firstword $(subst =, ,$(m))))
MAT_FILES  = $(wildcard *.ems) $(HSI_EMS)
# The goal is still scene.mk's `all` (this file's rules come first).
.DEFAULT_GOAL := all

# Band K's samples: min and max wavenumber at centre +- FWHM (cm-1, 3 decimals, so that
# bands a FWHM apart share the exact value), 5 samples; as .snd band lines.
define hsi_samples
!/^[ \t]*(#|$$)/ { k++; c = $$1; w = $$2; lo = sprintf("%.3f", 1e7 / (c + w)); \
  hi = sprintf("%.3f", 1e7 / (c - w)); inc = sprintf("%.5f", (hi - lo) / 4);
endef

$(SND): hawkeye.snd $(HSI_TABLE) | $(OUT)
	awk '$(hsi_samples) printf "%s %s %s\t# band %d: %g nm, FWHM %g nm\n", lo, hi, inc, k, c, w }' \
	  $(HSI_TABLE) > $@.bands
	awk -v n=$(BANDS) -v bands=$@.bands 'BEGIN { print "# hawkeye.snd with the bands of $(HSI_TABLE) (hyperspectral.mk)" } \
	  /^[ \t]*(#|$$)/ { next } { m++ } m == 1 { print; print n "\t# number of bands"; \
	    while ((getline l < bands) > 0) print l; next } m == 2 { nb = $$1; next } \
	  m >= 3 && m < 3 + nb { next } { print }' hawkeye.snd > $@
	rm -f $@.bands

## Each band's response: Gaussian of the table's FWHM about its centre, at the sample
## wavelengths 1e7 / (hi - i inc) nm, i = 0 to 4: the .rad's order, wavelength
## increasing (sen(5): count, gain, bias, responses).
$(SENS) &: $(HSI_TABLE) | $(OUT)
	mkdir -p $(OUT)/sen
	awk '$(hsi_samples) f = "$(OUT)/sen/band-" k ".sen"; \
	  printf "# band %d of $(HSI_TABLE): %g nm, FWHM %g nm (hyperspectral.mk)\n5\n1\n0\n", k, c, w > f; \
	  for (i = 0; i < 5; i++) { l = 1e7 / (hi - i * inc); \
	    printf "%.6f\t# %.3f nm\n", exp(-4 * log(2) * ((l - c) / w) ^ 2), l > f } close(f) }' $(HSI_TABLE)

## A material's spectrum over 0.35-2.6 um from data/spectra (wavelength um, reflectance)
## as an .ems: one curve, emissivity 1 - reflectance, fall-off 1 (as hawkeye's own .ems).
$(OUT)/vswir/%.ems: $(HSI_TABLE) | $(OUT)
	mkdir -p $(OUT)/vswir
	src=$(SPECTRA)/$(lastword $(subst =, ,$(filter $*.ems=%,$(HSI_SPECTRA)))).txt; \
	{ echo "# $*.ems for the hyperspectral view: 1 - reflectance of $$(basename $$src)"; \
	  sed -n 's/^#/# |/p' $$src | head -n 3; echo 1; for i in $$(seq 0 90); do echo 1; done; \
	  echo CURVE_BEGIN; awk '!/^#/ && $$1 >= 0.35 && $$1 <= 2.6 { printf "%s %.6g\n", $$1, 1 - $$2 }' $$src; \
	  echo CURVE_END; } > $@

## hawkeye.mat with those materials' .ems (in vswir/, beside this .mat) and every other
## .ems named by its path in the scene folder.
$(SCENE_MAT): hawkeye.mat $(HSI_EMS) | $(OUT)
	sed -e 's|^EMISSIVITY_FILE = \(.*\)$$|EMISSIVITY_FILE = $(CURDIR)/\1|' $(foreach m,$(HSI_SPECTRA),\
	  -e 's|^EMISSIVITY_FILE = $(CURDIR)/$(firstword $(subst =, ,$(m)))$$|EMISSIVITY_FILE = vswir/$(firstword $(subst =, ,$(m)))|') \
	  $< > $@
