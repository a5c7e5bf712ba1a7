# pipelines/scene.mk: the rules that chain sigchain's tools for one scene.
#
# A scene folder holds its inputs and a short Makefile that sets the variables below
# and includes this file; `make -C data/scenes/NAME` then rebuilds only what changed,
# into NAME/out/. `make help` lists the variables. See pipelines/README.md and
# sigchain(7), PIPELINES.
#
#   ANSWERS (+ .rsd) --control7--> out/DECK.cdk
#   ADV + SCENE_GDB [, CARDS_ADV + CARDS_GDB] --find_min_max_view_angle--> out/*.view
#   MTL (Landsat metadata, optional) --landsat_sensor--> out/landsat/NAME.snd and
#       out/landsat/NAME-bK.sen, used as SND and SENS                   (MTL set)
#   SND + out/*.view --(replace the view-angle line)--> out/NAME.snd, out/NAME.azimuth
#   out/DECK.cdk + out/NAME.snd --build_radiance (one run)--> out/NAME-K.rad (K = 1..BANDS)
#       (BUILD_RADIANCE_RUNS=band: out/NAME.snd --(one band each)--> out/band-K.snd, and one
#       run per band; the default for a program other than sigchain's build_radiance)
#   SND + SCENE_GDB + SCENE_MAT --trace --shadow-history--> out/NAME.shd    (WTH set)
#   out/NAME.shd + WTH + ... --therm--> out/NAME.tmp                       (WTH set)
#   ADV + out/NAME.snd + SCENE_GDB + SCENE_MAT + rads [+ tmp] --trace--> out/NAME.img
#       (TILES > 1: trace --rows per tile, out/NAME.tile-T.img, merged by this file)
#   CARDS_ADV + CARDS_GDB ... --trace--> out/cards.img --sensorize --calibrate-->
#       out/calibrated/*.sen                                              (CARDS_GDB set)
#   out/NAME.img + sens --sensorize--> out/NAME.tif (counts), out/NAME.png (preview:
#       true colour, the visible bands by wavelength; sensorize --preview)
#   out/NAME.tif + REFERENCE + CPT --compare--> out/NAME.report       (REFERENCE set)
#
# Every stage is a variable, so another program that reads and writes the same files
# (section 5 of the manual) can take its place, e.g. BUILD_RADIANCE=my_modtran_wrapper.

# A failing recipe leaves no target behind; no built-in rules or suffixes.
.DELETE_ON_ERROR:
.SUFFIXES:
MAKEFLAGS += --no-builtin-rules

SCENE_MK_DIR := $(patsubst %/,%,$(dir $(abspath $(lastword $(MAKEFILE_LIST)))))

## Where the tools are, one variable per stage --------------------------------------
# The build's tools beside the repository's scene.mk; an installed scene.mk
# (PREFIX/share/sigchain/pipelines) uses PREFIX/bin.
SIGCHAIN_BIN   ?= $(if $(filter %/share/sigchain/pipelines,$(SCENE_MK_DIR)),$(abspath \
  $(SCENE_MK_DIR)/../../../bin),$(SCENE_MK_DIR)/../build/bin)
CONTROL7       ?= $(SIGCHAIN_BIN)/control7
BUILD_RADIANCE ?= $(SIGCHAIN_BIN)/build_radiance
FIND_VIEW      ?= $(SIGCHAIN_BIN)/find_min_max_view_angle
TRACE          ?= $(SIGCHAIN_BIN)/trace
SHADOW         ?= $(SIGCHAIN_BIN)/trace --shadow-history
THERM          ?= $(SIGCHAIN_BIN)/therm
SENSORIZE      ?= $(SIGCHAIN_BIN)/sensorize
COMPARE        ?= $(SIGCHAIN_BIN)/compare
MERGE_TILES    ?= $(SIGCHAIN_BIN)/merge_tiles
LANDSAT_SENSOR ?= $(SIGCHAIN_BIN)/landsat_sensor

## Options per stage (the tools' warnings show; -q in a FLAGS variable hides them) ---
CONTROL7_FLAGS       ?=
BUILD_RADIANCE_FLAGS ?=
FIND_VIEW_FLAGS      ?=
TRACE_FLAGS          ?=
SHADOW_FLAGS         ?= --points-per-facet 16
THERM_FLAGS          ?=
CALIBRATE_FLAGS      ?=
SENSORIZE_FLAGS      ?=
COMPARE_FLAGS        ?=
LANDSAT_SENSOR_FLAGS ?=

## The scene's files (a scene's Makefile sets these) --------------------------------
NAME      ?= $(notdir $(CURDIR))
OUT       ?= out
ANSWERS   ?= $(NAME).answers
RSD       ?= $(wildcard *.rsd)
SND       ?= $(NAME).snd
ADV       ?= $(NAME).adv
SCENE_GDB ?= $(NAME).gdb
SCENE_MAT ?= $(NAME).mat
# Files the .mat names (read by trace and therm): a change to one reruns them.
MAT_FILES ?= $(wildcard *.ems *.ext *.asc)
SENS      ?= $(wildcard *.sen)
# Files an .odb scene places (.gdb, .obj, DEM rasters): a change to one reruns the
# stages that read the geometry.
GEOM_FILES ?=
# Optional: weather (thermal chain), calibration cards, reference image.
WTH       ?=
CARDS_GDB ?=
CARDS_ADV ?=
CARD1     ?=
CARD2     ?=
TARGET1   ?=
TARGET2   ?=
REFERENCE ?=
CPT       ?=
# A Landsat scene's metadata (mtl(5)): when set, landsat_sensor(1) makes the scene node and
# the .sen files into out/landsat/ from it, and they replace SND and SENS. LANDSAT_BANDS
# (comma-separated, e.g. 1,2,3,4) chooses the bands; by default landsat_sensor
# --print-bands says which, asked once as this file is read (it reads the MTL and writes
# nothing, so make -n stays harmless).
MTL ?=
ifneq ($(strip $(MTL)),)
ifeq ($(origin LANDSAT_BANDS),undefined)
LANDSAT_BANDS := $(shell $(LANDSAT_SENSOR) --print-bands $(LANDSAT_SENSOR_FLAGS) $(MTL))
endif
ifneq ($(if $(MAKECMDGOALS),$(filter-out clean help,$(MAKECMDGOALS)),all),)
$(if $(strip $(LANDSAT_BANDS)),,$(error MTL=$(MTL): no bands from $(LANDSAT_SENSOR) \
  --print-bands (its message is above); set LANDSAT_BANDS))
endif
LANDSAT_DIR := $(OUT)/landsat
comma := ,
SND   := $(LANDSAT_DIR)/$(NAME).snd
SENS  := $(foreach b,$(subst $(comma), ,$(LANDSAT_BANDS)),$(LANDSAT_DIR)/$(NAME)-b$(b).sen)
BANDS := $(words $(SENS))
endif
# Number of bands (from the .snd's second value line) and of row tiles.
BANDS ?= $(shell awk '!/^[ \t]*(\#|$$)/ { if (++n == 2) { print $$1; exit } }' $(SND))
TILES ?= 1
# The image's rows (the .adv's fifth value line).
ROWS  ?= $(shell awk '!/^[ \t]*(\#|$$)/ { if (++n == 5) { print $$1; exit } }' $(ADV))
# Emission from therm's temperatures in the cube: on when the scene has weather.
CUBE_TMP ?= $(if $(WTH),yes,no)
# How build_radiance runs: `all`, one run that writes every band's table (its threads
# share the bands' spectral samples; no process start, deck or gas-table reading per
# band: half the time of one run per band for visible bands, never more,
# bench/bands_cost.sh), or
# `band`, one run per band on a one-band scene node (each table a target of its own).
# The tables are byte for byte the same. A program put in BUILD_RADIANCE's place (one
# not named build_radiance) keeps the one-band interface, `band`, unless this says otherwise.
BUILD_RADIANCE_RUNS ?= $(if $(filter build_radiance,$(notdir $(firstword \
  $(BUILD_RADIANCE)))),all,band)
$(if $(filter all band,$(BUILD_RADIANCE_RUNS)),,$(error BUILD_RADIANCE_RUNS=$(BUILD_RADIANCE_RUNS): \
  expected all or band))

## Derived names --------------------------------------------------------------------
CDK       := $(OUT)/$(basename $(notdir $(ANSWERS))).cdk
RUN_SND   := $(OUT)/$(NAME).snd
AZIMUTH   := $(OUT)/$(NAME).azimuth
BAND_IDS  := $(shell seq 1 $(BANDS))
RADS      := $(foreach k,$(BAND_IDS),$(OUT)/$(NAME)-$(k).rad)
TILE_IDS  := $(shell seq 0 $$(($(TILES) - 1)))
TILE_IMGS := $(foreach t,$(TILE_IDS),$(OUT)/$(NAME).tile-$(t).img)
CUBE      := $(OUT)/$(NAME).img
SHD       := $(OUT)/$(NAME).shd
TMP       := $(OUT)/$(NAME).tmp
COUNTS    := $(OUT)/$(NAME).tif
PREVIEW   := $(OUT)/$(NAME).png
REPORT    := $(OUT)/$(NAME).report
VIEWS     := $(OUT)/$(NAME).view $(if $(CARDS_GDB),$(OUT)/cards.view)
CARDS_CUBE := $(OUT)/cards.img
# The .sen files sensorize uses for the counts: calibrated when there are cards.
CAL_SENS  := $(addprefix $(OUT)/calibrated/,$(notdir $(SENS)))
COUNT_SENS := $(if $(CARDS_GDB),$(CAL_SENS),$(SENS))
TRACE_TMP := $(if $(filter yes,$(CUBE_TMP)),$(TMP))

## Each stage's command (program and options, without the files it reads and writes,
## which the rules name) -------------------------------------------------------------
CMD_control7       = $(strip $(CONTROL7) $(CONTROL7_FLAGS))
CMD_find_view      = $(strip $(FIND_VIEW) $(FIND_VIEW_FLAGS))
CMD_build_radiance = $(strip $(BUILD_RADIANCE) $(BUILD_RADIANCE_FLAGS))
CMD_shadow         = $(strip $(SHADOW) $(SHADOW_FLAGS))
CMD_therm          = $(strip $(THERM) $(THERM_FLAGS))
CMD_trace          = $(strip $(TRACE) $(TRACE_FLAGS) $(if $(TRACE_TMP),--tmp $(TRACE_TMP)))
CMD_calibrate      = $(SENSORIZE) --calibrate $(CALIBRATE_FLAGS) --card1 $(CARD1) \
  --card2 $(CARD2) --target1 $(TARGET1) --target2 $(TARGET2)
CMD_sensorize      = $(strip $(SENSORIZE) $(SENSORIZE_FLAGS))
CMD_compare        = $(strip $(COMPARE) $(COMPARE_FLAGS))
CMD_landsat_sensor = $(strip $(LANDSAT_SENSOR) $(LANDSAT_SENSOR_FLAGS) --bands $(LANDSAT_BANDS) \
  --name $(NAME))
STAGES := control7 find_view build_radiance shadow therm trace calibrate sensorize \
  compare $(if $(strip $(MTL)),landsat_sensor)
# $(call CMD_STAMP,STAGE): the file that records STAGE's command, a prerequisite of
# what the stage makes. It is rewritten when this file is read, and only when the
# command differs from the one recorded, so that BUILD_RADIANCE=..., TRACE_FLAGS=...
# rerun that stage (and the stages after it) and a rerun with the same command does
# nothing (make -q included; make -n records the command too). The new text goes to
# a file of the shell's own (.PID), since the make that a recipe below starts again
# reads this file too, perhaps two at once under make -j.
CMD_STAMP = $(OUT)/$(1).cmd.stamp
define record_cmd
$(shell mkdir -p $(OUT) && f=$(call CMD_STAMP,$(1)) && n=$$f.$$$$ && \
  printf '%s\n' '$(subst ','\'',$(strip $(CMD_$(1))))' > $$n && \
  if cmp -s $$n $$f; then rm -f $$n; else mv -f $$n $$f; fi)
endef
ifneq ($(if $(MAKECMDGOALS),$(filter-out clean help,$(MAKECMDGOALS)),all),)
RECORDED_CMDS := $(foreach stage,$(STAGES),$(call record_cmd,$(stage)))
endif

# Files made by pattern rules stay after the build (else make removes them as
# intermediate and remakes them next time).
.SECONDARY: $(CDK) $(foreach k,$(BAND_IDS),$(OUT)/band-$(k).snd) $(TILE_IMGS) \
  $(TILE_IMGS:.img=.hdr)

.PHONY: all rad view cube counts preview thermal calibrate report clean help
all: counts preview $(if $(REFERENCE),report) $(if $(WTH),thermal)
rad: $(RADS)
view: $(RUN_SND)
cube: $(CUBE)
counts: $(COUNTS)
preview: $(PREVIEW)
thermal: $(TMP)
calibrate: $(if $(CARDS_GDB),$(CAL_SENS))
report: $(REPORT)

$(OUT) $(OUT)/calibrated:
	mkdir -p $@

## control7: the answers (and the radiosonde they name, opened from the scene folder)
## -> LOWTRAN 7 card deck.
$(OUT)/%.cdk: %.answers $(RSD) $(call CMD_STAMP,control7) | $(OUT)
	$(CMD_control7) --answers $< -o $@

ifneq ($(strip $(MTL)),)
## landsat_sensor: the Landsat scene's metadata -> its scene node and one .sen per band,
## written as one set (the response tables come from the data directory or --rsr).
$(SND) $(SENS) &: $(MTL) $(call CMD_STAMP,landsat_sensor) | $(OUT)
	$(CMD_landsat_sensor) $(MTL) -o $(LANDSAT_DIR)
endif

## find_min_max_view_angle: the view-angle range of a camera over its scene: the
## .snd line (--snd), then the full report (which names the look azimuth).
## (The camera and the scene are the first two prerequisites; GEOM_FILES, the files an
## .odb places, only make the range depend on them.)
define find_view
$(CMD_find_view) --snd $(wordlist 1,2,$^) > $@
$(CMD_find_view) $(wordlist 1,2,$^) >> $@
endef
$(OUT)/$(NAME).view: $(ADV) $(SCENE_GDB) $(GEOM_FILES) $(call CMD_STAMP,find_view) | $(OUT)
	$(find_view)
$(OUT)/cards.view: $(CARDS_ADV) $(CARDS_GDB) $(call CMD_STAMP,find_view) | $(OUT)
	$(find_view)

## The scene node used downstream: SND with its view-angle line replaced by the union
## of the ranges in out/*.view (rounded outward to the smallest increment), and the
## look azimuth for build_radiance --view-azimuth. Each file is replaced only when
## its content changes, so a camera move that keeps the range does not rerun
## build_radiance; the stamp records that the check ran.
$(OUT)/$(NAME).snd.stamp: $(SND) $(VIEWS) | $(OUT)
	awk 'FNR == 1 { seen = 0 } !/^[ \t]*#/ && NF >= 3 && !seen { seen = 1; \
	    if (n++ == 0 || $$1 < lo) lo = $$1; if ($$2 > hi || n == 1) hi = $$2; \
	    if ($$3 < inc || n == 1) inc = $$3 } \
	  function fl(x) { return x == int(x) || x >= 0 ? int(x) : int(x) - 1 } \
	  END { e = 1e-9; lo = fl(lo / inc + e) * inc; hi = -fl(-hi / inc + e) * inc; \
	    printf "%g %g %g\n", lo, hi, inc }' $(VIEWS) > $@.range
	awk -v range="$$(cat $@.range)" '/^[ \t]*(#|$$)/ { print; next } \
	  { n++ } n == 2 { nb = $$1 } n == 3 + nb { \
	    print range "\t# view angles: min, max, increment (deg), find_min_max_view_angle"; next } \
	  { print }' $(SND) > $(RUN_SND).new
	sed -n 's/.*positive toward azimuth \([-0-9.]*\).*/\1/p' $(OUT)/$(NAME).view | head -n 1 \
	  > $(AZIMUTH).new
	test -s $(AZIMUTH).new
	for f in $(RUN_SND) $(AZIMUTH); do \
	  if cmp -s $$f.new $$f; then rm -f $$f.new; else mv -f $$f.new $$f; fi; done
	rm -f $@.range
	touch $@
$(RUN_SND) $(AZIMUTH): $(OUT)/$(NAME).snd.stamp
	@test -f $@ || { rm -f $<; $(MAKE) --no-print-directory $<; }

ifeq ($(BUILD_RADIANCE_RUNS),all)
## build_radiance: card deck + scene node -> every band's radiance table in one run.
## Called as BUILD_RADIANCE [FLAGS] --view-azimuth DEG CDK SND -o out/NAME-%d.rad.
$(RADS) &: $(CDK) $(RUN_SND) $(AZIMUTH) $(call CMD_STAMP,build_radiance)
	$(CMD_build_radiance) --view-azimuth $$(cat $(AZIMUTH)) \
	  $(CDK) $(RUN_SND) -o $(OUT)/$(NAME)-%d.rad
else
## One scene node per band (band K alone), so that each band's .rad is a target of its
## own and `make -j` runs bands in parallel.
$(OUT)/band-%.snd: $(RUN_SND)
	awk -v k=$* '/^[ \t]*(#|$$)/ { print; next } { n++ } \
	  n == 2 { nb = $$1; print "1\t# number of bands (band " k " of " nb ")"; next } \
	  n >= 3 && n < 3 + nb && n != 2 + k { next } { print }' $< > $@

## build_radiance: card deck + one-band scene node -> that band's radiance table.
## Called as BUILD_RADIANCE [FLAGS] --view-azimuth DEG CDK SND -o FILE.rad.
$(OUT)/$(NAME)-%.rad: $(CDK) $(OUT)/band-%.snd $(AZIMUTH) $(call CMD_STAMP,build_radiance)
	$(CMD_build_radiance) --view-azimuth $$(cat $(AZIMUTH)) \
	  $(CDK) $(OUT)/band-$*.snd -o $@
endif

## trace --shadow-history: 24 h of sun and shadow per facet, for therm.
$(SHD): $(SND) $(SCENE_GDB) $(SCENE_MAT) $(MAT_FILES) $(GEOM_FILES) $(call CMD_STAMP,shadow) | $(OUT)
	$(CMD_shadow) $(SND) $(SCENE_GDB) $(SCENE_MAT) -o $@

## therm: shadow history + weather -> facet temperatures.
$(TMP): $(SHD) $(WTH) $(SCENE_MAT) $(SCENE_GDB) $(SND) $(MAT_FILES) $(GEOM_FILES) \
  $(call CMD_STAMP,therm)
	$(CMD_therm) $(SHD) $(WTH) $(SCENE_MAT) $(SCENE_GDB) $(SND) -o $@

## trace: the radiance cube (with emission from out/NAME.tmp when CUBE_TMP=yes).
TRACE_INPUTS := $(ADV) $(RUN_SND) $(SCENE_GDB) $(SCENE_MAT) $(RADS)
define trace_cube
$(CMD_trace) $(2) $(TRACE_INPUTS) -o $(1)
endef
ifeq ($(TILES),1)
$(CUBE) $(basename $(CUBE)).hdr &: $(TRACE_INPUTS) $(MAT_FILES) $(GEOM_FILES) $(TRACE_TMP) \
  $(call CMD_STAMP,trace)
	$(call trace_cube,$(CUBE))
else
## trace --rows: tile T holds rows T*ROWS/TILES to (T+1)*ROWS/TILES - 1.
$(OUT)/$(NAME).tile-%.img $(OUT)/$(NAME).tile-%.hdr: $(TRACE_INPUTS) $(MAT_FILES) $(GEOM_FILES) \
  $(TRACE_TMP) $(call CMD_STAMP,trace)
	$(call trace_cube,$(OUT)/$(NAME).tile-$*.img,--rows $$(($* * $(ROWS) / $(TILES))):$$((($* + 1) * $(ROWS) / $(TILES))))

## Merge the tiles with merge_tiles(1): it checks that they come from one render (the
## same inputs, options and sigchain; every row once) and writes the cube bit-identical
## to an untiled render, its recorded command that of an untiled render.
$(CUBE) $(basename $(CUBE)).hdr &: $(TILE_IMGS) $(call CMD_STAMP,trace)
	$(MERGE_TILES) -q $(TILE_IMGS) -o $(CUBE)
endif

ifneq ($(CARDS_GDB),)
## The calibration scene: trace the cards with the same tables, then
## sensorize --calibrate derives each band's gain and bias (White (1996), section 4.2.4) into
## out/calibrated/ (its table of radiances and counts into out/calibration.txt).
$(CARDS_CUBE) $(basename $(CARDS_CUBE)).hdr &: $(CARDS_ADV) $(RUN_SND) $(CARDS_GDB) $(SCENE_MAT) \
  $(MAT_FILES) $(RADS) $(call CMD_STAMP,trace)
	$(TRACE) $(TRACE_FLAGS) $(CARDS_ADV) $(RUN_SND) $(CARDS_GDB) $(SCENE_MAT) $(RADS) -o $(CARDS_CUBE)
$(CAL_SENS) $(OUT)/calibration.txt &: $(CARDS_CUBE) $(SENS) $(call CMD_STAMP,calibrate) \
  | $(OUT)/calibrated
	$(CMD_calibrate) $(CARDS_CUBE) $(SENS) -o $(OUT)/calibrated \
	  > $(OUT)/calibration.txt
endif

## sensorize: radiance cube -> digital counts (TIFF) and, in the same run, their
## true-colour preview (8-bit PNG: of the bands centred in 0.38-0.78 um, red the
## longest, blue the shortest, green the one nearest 0.55 um; sensorize(1) --preview).
## A program put in SENSORIZE's place takes --preview FILE.png too.
$(COUNTS) $(PREVIEW) &: $(CUBE) $(COUNT_SENS) $(call CMD_STAMP,sensorize)
	$(CMD_sensorize) $(CUBE) $(COUNT_SENS) -o $(COUNTS) --preview $(PREVIEW)

## compare: counts against the reference image at the control points -> report.
$(REPORT): $(COUNTS) $(REFERENCE) $(CPT) $(call CMD_STAMP,compare)
	$(CMD_compare) $(COUNTS) $(REFERENCE) $(CPT) -o $@

clean:
	rm -rf $(OUT)

help:
	@echo 'make [TARGET] [VARIABLE=VALUE ...] in a scene folder (pipelines/scene.mk)'
	@echo 'targets: all (counts, preview, report, thermal), rad, view, cube, counts,'
	@echo '  preview, thermal, calibrate, report, clean, help'
	@echo 'stages (programs): CONTROL7 BUILD_RADIANCE FIND_VIEW TRACE SHADOW THERM'
	@echo '  SENSORIZE COMPARE LANDSAT_SENSOR; default $$(SIGCHAIN_BIN)/TOOL, SIGCHAIN_BIN=$(SIGCHAIN_BIN)'
	@echo 'options: CONTROL7_FLAGS BUILD_RADIANCE_FLAGS FIND_VIEW_FLAGS TRACE_FLAGS'
	@echo '  SHADOW_FLAGS THERM_FLAGS CALIBRATE_FLAGS SENSORIZE_FLAGS'
	@echo '  COMPARE_FLAGS LANDSAT_SENSOR_FLAGS (a changed program or option reruns its'
	@echo '  stage: out/STAGE.cmd.stamp)'
	@echo 'Landsat: MTL=$(MTL) (landsat_sensor writes SND and SENS into out/landsat)'
	@echo '  LANDSAT_SENSOR=$(LANDSAT_SENSOR) LANDSAT_BANDS=$(LANDSAT_BANDS)'
	@echo 'this file: SCENE_MK=$(SCENE_MK_DIR)/scene.mk'
	@echo 'scene: NAME=$(NAME) OUT=$(OUT) ANSWERS=$(ANSWERS) RSD=$(RSD) SND=$(SND)'
	@echo '  ADV=$(ADV) SCENE_GDB=$(SCENE_GDB) SCENE_MAT=$(SCENE_MAT) MAT_FILES=$(MAT_FILES)'
	@echo '  GEOM_FILES=$(GEOM_FILES) SENS=$(SENS) WTH=$(WTH) CUBE_TMP=$(CUBE_TMP)'
	@echo '  CARDS_GDB=$(CARDS_GDB) CARDS_ADV=$(CARDS_ADV) CARD1=$(CARD1) CARD2=$(CARD2)'
	@echo '  TARGET1=$(TARGET1) TARGET2=$(TARGET2) REFERENCE=$(REFERENCE) CPT=$(CPT)'
	@echo 'parallelism: BANDS=$(BANDS) (one .rad each), BUILD_RADIANCE_RUNS=$(BUILD_RADIANCE_RUNS)'
	@echo '  (all: one build_radiance run for every band; band: one run per band), TILES=$(TILES)'
	@echo '  (trace --rows tiles of ROWS=$(ROWS) rows, merged); use make -j'
