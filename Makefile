# aero: physically based aerodynamic sound for Pure Data.
#
#   make            externals (one per object), the core library, aerotex
#   make lib        the single-binary library aero.pd_linux (aero_setup())
#   make check      every test CI runs (installs missing dependencies first)
#   make check-pd056  the Pd tests again under Pd 0.56 (single and double
#                   precision, 48 kHz), built from ../shared/vendor
#   make double     the externals for double-precision Pd (*.linux-amd64-64.so)
#   make deken      deken packages (single, double, sources) in build/deken/
#   make check-gui  the help patches drawn by the Pd GUI (part of check)
#   make check-libpd  aero inside libpd 0.16.1 (single, multi-instance,
#                   threads under helgrind); CI runs it after make check
#   make demo       renders the demo scenes under build/demo/
#   make bench      benchmarks (not part of check), see BENCHMARKS.md
#   make deps       installs the Debian packages the project needs
#   make install    installs into Pd's externals folder (pd-lib-builder)
#
# The Pd externals are built by pd-lib-builder: a copy in pd-lib-builder/ if
# one is placed there, otherwise Debian's package (never copied into this tree).

lib.name = aero

# --- the Pd side: one external per object, plus the single-binary setup ----
class.sources = $(sort $(wildcard src/pd/*~.c))
lib.setup.sources = src/pd/aero.c
# the skeleton every wrapper shares, linked into each external and the lib
common.sources = src/pd/aero_pd.c

datafiles = $(wildcard help/*.pd) $(wildcard abstractions/*.pd) \
    README.md LICENSE
datadirs = $(if $(wildcard textures/*.wav),textures)
datadirs += $(if $(wildcard trees/*.tree),trees)

# No -ffast-math: the core relies on NaN checks (x != x) to sanitise input.
CFLAGS = -Wall -Wextra -Wshadow -O3 -funroll-loops -fomit-frame-pointer
# src/core by role: common (shared data and laws), solve (the flow solvers
# and the drivers that make textures), play (the real-time players)
CORE_INCLUDES = -Isrc/core/common -Isrc/core/solve -Isrc/core/play
cflags = -std=c99 -D_POSIX_C_SOURCE=200809L $(CORE_INCLUDES)
ldlibs = build/libaero_core.a -lsndfile -lfftw3f_threads -lfftw3f -lm

PDLIBBUILDER_DIR ?= $(if $(wildcard pd-lib-builder/Makefile.pdlibbuilder),\
    pd-lib-builder,/usr/share/pd-lib-builder)

ifneq ($(wildcard $(PDLIBBUILDER_DIR)/Makefile.pdlibbuilder),)
include $(PDLIBBUILDER_DIR)/Makefile.pdlibbuilder
else
all:
	@echo "pd-lib-builder is missing: run 'make deps' first" >&2; exit 1
endif

# --- the host-independent core: build/libaero_core.a ------------------------
BUILD = build
CORE_CC = $(CC)
CORE_CFLAGS = -std=c99 -D_POSIX_C_SOURCE=200809L -O3 -fPIC -fopenmp \
    -Wall -Wextra -Wshadow $(CORE_INCLUDES)
# the 3D solver's row loops (flow3d.c) vectorise only where a conversion
# between int and float may run unconditionally: -fno-trapping-math (nothing
# here reads the FP exception flags; the IEEE results are the same), and
# its square roots (vorticity, confinement) only without errno:
# -fno-math-errno (nothing reads errno after them; sqrtf is correctly
# rounded either way). Its trilinear sampler is fastest with AVX2 gathers,
# which GCC's generic tuning leaves out: asked for where the compiler knows
# the option
F3_GATHER := $(shell $(CC) -mtune-ctrl=use_gather -x c -c -o /dev/null \
    /dev/null 2>/dev/null && echo -mtune-ctrl=use_gather)
$(BUILD)/core/solve/flow3d.o: CORE_CFLAGS += -fno-trapping-math -fno-math-errno \
    $(F3_GATHER)
core.sources = $(sort $(wildcard src/core/*/*.c))
core.objects = $(patsubst src/core/%.c,$(BUILD)/core/%.o,$(core.sources))
core.lib = $(BUILD)/libaero_core.a
TOOL_LIBS = $(core.lib) -lsndfile -lfftw3 -lfftw3f_threads -lfftw3f -lpng -lm -fopenmp

$(BUILD)/core/%.o: src/core/%.c $(wildcard src/core/*/*.h)
	@mkdir -p $(dir $@)
	$(CORE_CC) $(CORE_CFLAGS) -c $< -o $@

$(core.lib): $(core.objects)
	@mkdir -p $(dir $@)
	rm -f $@
	ar rcs $@ $^

# externals and the lib binary link the core archive
$(classes.executables) $(lib.name).$(extension): $(core.lib)

# --- tools: aerotex and the test analyser -----------------------------------
aerotex.sources = $(sort $(wildcard src/tools/aerotex*.c))
analyze.sources = tests/analyze/aero-analyze.c

$(BUILD)/aerotex: $(aerotex.sources) $(core.lib) $(wildcard src/tools/*.h)
	$(CORE_CC) $(CORE_CFLAGS) $(aerotex.sources) -o $@ $(TOOL_LIBS)

$(BUILD)/aero-analyze: $(analyze.sources) $(core.lib)
	$(CORE_CC) $(CORE_CFLAGS) $(analyze.sources) -o $@ $(TOOL_LIBS)

# --- unit tests of src/core: one binary per tests/unit/test_*.c -------------
unit.sources = $(sort $(wildcard tests/unit/test_*.c))
unit.binaries = $(patsubst tests/unit/%.c,$(BUILD)/tests/%,$(unit.sources))

$(BUILD)/tests/%: tests/unit/%.c $(wildcard tests/unit/*.h) $(core.lib)
	@mkdir -p $(dir $@)
	$(CORE_CC) $(CORE_CFLAGS) $< -o $@ $(TOOL_LIBS)

.PHONY: tools lib pdinstance deps check check-only check-pd056 check-gui demo bench textures deken libpd-example

all: tools
tools: $(BUILD)/aerotex $(BUILD)/aero-analyze $(unit.binaries)

# the single binary (what a libpd app links); built by a second
# pd-lib-builder pass that reuses the same object files
lib: all
	$(MAKE) --no-print-directory make-lib-executable=yes

# --- double precision: the same externals for a Pd built with
# PD_FLOATSIZE=64, named *.OS-ARCH-64.so as pd-lib-builder's floatsize=64
# names them (Debian's pd-lib-builder 0.6 predates that, so the rules are
# here). They sit beside the single-precision ones; each wrapper converts
# its signals at the boundary, the core archive is the same float core.
DOUBLE_EXT = $(shell uname -s | tr A-Z a-z)-$(shell uname -m | \
    sed 's/x86_64/amd64/; s/aarch64/arm64/')-64.so
double.externals = $(patsubst src/pd/%.c,%.$(DOUBLE_EXT),$(class.sources))
double.lib = $(lib.name).$(DOUBLE_EXT)
DOUBLE_CFLAGS = -DPD -DUNIX -DPD_FLOATSIZE=64 -I/usr/include/pd \
    $(cflags) $(CFLAGS) -fPIC -shared -rdynamic
%~.$(DOUBLE_EXT): src/pd/%~.c $(common.sources) src/pd/aero_pd.h $(core.lib)
	$(CC) $(DOUBLE_CFLAGS) $< $(common.sources) -o $@ $(ldlibs)
$(double.lib): $(lib.setup.sources) $(class.sources) $(common.sources) \
    src/pd/aero_pd.h $(core.lib)
	$(CC) $(DOUBLE_CFLAGS) $(lib.setup.sources) $(class.sources) \
	    $(common.sources) -o $@ $(ldlibs)
.PHONY: double
double: $(double.externals) $(double.lib)

# make install: besides pd-lib-builder's externals and data, the single
# binary (for [declare -lib aero]) and the double-precision binaries
.PHONY: install-aero
install: install-aero
install-aero: lib double
	$(INSTALL_DIR) "$(installpath)"
	$(INSTALL_PROGRAM) $(lib.name).$(extension) $(double.externals) \
	    $(double.lib) "$(installpath)"

# the wrappers must also compile for multi-instance libpd
pdinstance:
	@for f in $(class.sources) $(lib.setup.sources) $(common.sources); do \
	    $(CC) -std=c99 -fsyntax-only -Wall -Wextra -Werror \
	        -DPDINSTANCE -DPDTHREADS -I/usr/include/pd $(CORE_INCLUDES) $$f \
	        || exit 1; \
	done; echo "wrappers compile with -DPDINSTANCE -DPDTHREADS"

# --- dependencies: Debian packages ------------------------------------------
DEB_PACKAGES = puredata-core puredata-dev pd-lib-builder libfftw3-dev \
    libsndfile1-dev libpng-dev sox gcc make valgrind zip git
# the GUI check of the help patches (tests/gui): Pd's GUI under Xvfb,
# screenshots by ImageMagick's import, the font Pd draws its boxes with
DEB_PACKAGES += puredata-gui xvfb xauth imagemagick fonts-dejavu-core
deps:
	@sh tests/deps.sh $(DEB_PACKAGES)

# --- the two commands of the README -----------------------------------------
check:
	@$(MAKE) --no-print-directory deps
	@$(MAKE) --no-print-directory -s all lib >$(BUILD).log 2>&1 || \
	    { cat $(BUILD).log; exit 1; }
	@sh tests/run.sh

# the Pd tests under Pd 0.56-5 (built in build/pd056 from ../shared/vendor),
# single and double precision, at 48 kHz
check-pd056:
	@$(MAKE) --no-print-directory deps
	@$(MAKE) --no-print-directory -s all lib double >$(BUILD).log 2>&1 || \
	    { cat $(BUILD).log; exit 1; }
	@sh tests/check-pd056.sh
# only the GUI check of the help patches (part of check): screenshots in
# build/gui/; check-gui HELP="help/x-help.pd ..." checks some of them
check-gui:
	@$(MAKE) --no-print-directory deps
	@$(MAKE) --no-print-directory -s all >$(BUILD).log 2>&1 || \
	    { cat $(BUILD).log; exit 1; }
	@sh tests/gui/check-help.sh $(HELP)

demo:
	@$(MAKE) --no-print-directory deps
	@$(MAKE) --no-print-directory -s all >/dev/null
	@sh tests/demo.sh

bench:
	@$(MAKE) --no-print-directory deps
	@$(MAKE) --no-print-directory -s all >/dev/null
	@sh bench/run.sh

textures:
	@$(MAKE) --no-print-directory -s tools
	@sh textures/make.sh

# --- packaging: deken packages (the Pd package manager's format) ----------
# A deken package is a zip archive of the library folder named
# NAME[vVERSION](OS-ARCH-FLOATSIZE).dek: one for single-precision Pd
# (*.pd_linux), one for double precision (*.linux-amd64-64.so), and the
# (Sources) package; each .dek.txt lists the objects with the DESCRIPTION of
# their help patch's META, each .sha256 is the archive's checksum
# (sha256sum -c). The version is the one of help/aero-meta.pd. (Debian's
# `deken` tool cannot run offline: it fetches its hy runtime from PyPI, so
# the archives are made here with zip, in the same format.)
AERO_VERSION = $(shell sed -n 's/^\#X text [0-9]* [0-9]* VERSION \([0-9][0-9.]*\).*/\1/p' \
    help/aero-meta.pd | head -n 1)
DEKEN_DIR = $(BUILD)/deken
DEKEN_ARCH = $(shell uname -s)-$(shell uname -m | sed 's/x86_64/amd64/; s/aarch64/arm64/')
DEKEN_NAME = aero[v$(AERO_VERSION)]
DEB_PACKAGES += unzip # the packaging test unpacks the .dek files
deken.objects = $(class.sources:src/pd/%.c=%) \
    $(patsubst abstractions/%.pd,%,$(wildcard abstractions/*.pd))
deken: all
	@test -n "$(AERO_VERSION)" || { echo "no VERSION in help/aero-meta.pd" >&2; exit 1; }
	rm -rf $(DEKEN_DIR)
	$(MAKE) --no-print-directory -s install PDLIBDIR=$(CURDIR)/$(DEKEN_DIR)/stage
	cd $(DEKEN_DIR)/stage && \
	    zip -q -r "../$(DEKEN_NAME)($(DEKEN_ARCH)-32).dek" aero -x '*-64.so' && \
	    zip -q -r "../$(DEKEN_NAME)($(DEKEN_ARCH)-64).dek" aero -x '*.pd_linux'
	git archive --format=zip --prefix=aero/ \
	    -o "$(DEKEN_DIR)/$(DEKEN_NAME)(Sources).dek" HEAD
	sh tests/deken-objects.sh $(deken.objects) >$(DEKEN_DIR)/objects.txt
	cd $(DEKEN_DIR) && for f in *.dek; do \
	    cp objects.txt "$$f.txt" && sha256sum "$$f" >"$$f.sha256"; done
	rm -rf $(DEKEN_DIR)/stage $(DEKEN_DIR)/objects.txt
	@ls -1 $(DEKEN_DIR)/*.dek*

# --- libpd: aero linked into a host program -------------------------------
#   make libpd-example LIBPD_DIR=/path/to/libpd
# builds examples/libpd-host.c with every class and aero.c (one
# aero_setup()) against a built libpd: single-instance (`make STATIC=true`)
# or multi-instance (`make STATIC=true MULTI=true`), detected from the
# library (pd_this exists only in a multi-instance build; LIBPD_MULTI=yes|no
# overrides), linked statically with libs/libpd.a when it exists, else with
# libpd.so and an rpath (LIBPD_LINK=static|shared overrides). Against a
# shared single-instance libpd the wrappers must be position-independent
# (-fPIC): README.md, "Embedding with libpd".
#   make check-libpd  builds libpd 0.16.1 from ../shared/vendor into
#                     build/libpd/ (both variants, once) and runs
#                     tests/libpd/run.sh; skipped without the archives
LIBPD_DIR ?=
LIBPD_HOST ?= $(BUILD)/libpd-host
LIBPD_LINK ?= $(if $(wildcard $(LIBPD_DIR)/libs/libpd.a),static,shared)
LIBPD_LIB = $(LIBPD_DIR)/libs/libpd.$(if $(filter static,$(LIBPD_LINK)),a,so)
LIBPD_MULTI ?= $(shell nm $(LIBPD_LIB) 2>/dev/null | grep -qw pd_this && echo yes || echo no)
libpd.cflags = -std=c99 -D_POSIX_C_SOURCE=200809L -O2 -Wall -Wextra \
    $(if $(filter yes,$(LIBPD_MULTI)),-DPDINSTANCE -DPDTHREADS) \
    $(if $(filter shared,$(LIBPD_LINK)),-fPIC) -DHAVE_LIBPD \
    -I$(LIBPD_DIR)/libpd_wrapper -I$(LIBPD_DIR)/pure-data/src -Isrc/pd $(CORE_INCLUDES)
libpd.libs = $(if $(filter static,$(LIBPD_LINK)),$(LIBPD_LIB),\
    -L$(LIBPD_DIR)/libs -lpd -Wl,-rpath,$(abspath $(LIBPD_DIR)/libs)) \
    $(core.lib) -lsndfile -lfftw3f_threads -lfftw3f -lm -lpthread -ldl
libpd-example: $(core.lib)
	@test -f "$(LIBPD_LIB)" || { echo "set LIBPD_DIR to a built libpd" \
	    "(no $(LIBPD_LIB))" >&2; exit 1; }
	@echo "libpd: $(LIBPD_DIR), $(if $(filter yes,$(LIBPD_MULTI)),multi-instance,single-instance), $(LIBPD_LINK)"
	$(CC) $(libpd.cflags) examples/libpd-host.c $(class.sources) \
	    $(lib.setup.sources) $(common.sources) $(libpd.libs) -o $(LIBPD_HOST)
	@echo "run: $(LIBPD_HOST) examples . $(BUILD)/sword-swing.wav"

.PHONY: check-libpd
check-libpd:
	@$(MAKE) --no-print-directory deps
	@$(MAKE) --no-print-directory -s all >$(BUILD).log 2>&1 || \
	    { cat $(BUILD).log; exit 1; }
	@sh tests/libpd/run.sh

clean: clean-aero
clean-aero:
	rm -rf $(BUILD) $(BUILD).log $(double.externals) $(double.lib)

# ============================================================================
# --- robustness: sanitizers, fuzzing, long runs, globals --------
#   make check-asan   unit tests + Pd batch tests under ASan/UBSan (gcc),
#                     instrumented externals loaded into Pd with libasan
#                     preloaded, then check-valgrind
#   make check-valgrind  the core unit tests under valgrind memcheck, but
#                     those declared slow (tests/robust/slow-tests.sh)
#   ONLY=pattern      scopes both, as in tests/run.sh (ONLY=aeolian)
#   make fuzz         libFuzzer harnesses of fuzz/targets.txt (FUZZ_SECONDS
#                     per harness, default 300)
#   make check-long   one hour of audio per line of tests/robust/long.txt
#   make check-globals  no writable globals in src/ (nm)
# Everything builds under build-asan/ and build-fuzz/; build/ is untouched.
# ============================================================================
DEB_PACKAGES += clang libclang-rt-14-dev
ASAN_DIR = build-asan
ASAN_CC = gcc
# float-cast-overflow is not part of gcc's 'undefined': (int) of a NaN or
# huge float from a patch is exactly what hostile input produces
ASAN_FLAGS = -g -O1 -fno-omit-frame-pointer -fsanitize=address,undefined \
    -fsanitize=float-cast-overflow -fno-sanitize-recover=undefined,float-cast-overflow
ASAN_CFLAGS = -std=c99 -D_POSIX_C_SOURCE=200809L -fPIC -fopenmp \
    -Wall -Wextra -Wshadow $(CORE_INCLUDES) $(ASAN_FLAGS)
ASAN_ROOT = $(ASAN_DIR)/root
asan.core.objects = $(patsubst src/core/%.c,$(ASAN_DIR)/core/%.o,$(core.sources))
asan.lib = $(ASAN_DIR)/libaero_core.a
asan.externals = $(patsubst src/pd/%.c,$(ASAN_ROOT)/%.pd_linux,$(class.sources))
asan.tools = $(ASAN_ROOT)/build/aerotex $(ASAN_ROOT)/build/aero-analyze \
    $(patsubst tests/unit/%.c,$(ASAN_ROOT)/build/tests/%,$(unit.sources))
ASAN_PD_CFLAGS = -DPD -DUNIX -I/usr/include/pd -shared $(ASAN_CFLAGS)

$(ASAN_DIR)/core/%.o: src/core/%.c $(wildcard src/core/*/*.h)
	@mkdir -p $(dir $@)
	$(ASAN_CC) $(ASAN_CFLAGS) -c $< -o $@
$(asan.lib): $(asan.core.objects)
	rm -f $@; ar rcs $@ $^
$(ASAN_ROOT)/%~.pd_linux: src/pd/%~.c $(common.sources) src/pd/aero_pd.h $(asan.lib)
	@mkdir -p $(dir $@)
	$(ASAN_CC) $(ASAN_PD_CFLAGS) $< $(common.sources) -o $@ $(asan.lib) \
	    -lsndfile -lfftw3f_threads -lfftw3f -lm
$(ASAN_ROOT)/aero.pd_linux: $(lib.setup.sources) $(class.sources) $(common.sources) $(asan.lib)
	$(ASAN_CC) $(ASAN_PD_CFLAGS) $(lib.setup.sources) $(class.sources) $(common.sources) -o $@ \
	    $(asan.lib) -lsndfile -lfftw3f_threads -lfftw3f -lm
$(ASAN_ROOT)/build/aerotex: $(aerotex.sources) $(asan.lib)
	@mkdir -p $(dir $@)
	$(ASAN_CC) $(ASAN_CFLAGS) $(aerotex.sources) -o $@ \
	    $(subst $(core.lib),$(asan.lib),$(TOOL_LIBS))
$(ASAN_ROOT)/build/aero-analyze: $(analyze.sources) $(asan.lib)
	@mkdir -p $(dir $@)
	$(ASAN_CC) $(ASAN_CFLAGS) $(analyze.sources) -o $@ \
	    $(subst $(core.lib),$(asan.lib),$(TOOL_LIBS))
$(ASAN_ROOT)/build/tests/%: tests/unit/%.c $(wildcard tests/unit/*.h) $(asan.lib)
	@mkdir -p $(dir $@)
	$(ASAN_CC) $(ASAN_CFLAGS) $< -o $@ \
	    $(subst $(core.lib),$(asan.lib),$(TOOL_LIBS))

.PHONY: asan check-asan check-valgrind fuzz fuzz-build check-long check-globals \
    check-convergence
asan: $(asan.externals) $(ASAN_ROOT)/aero.pd_linux $(asan.tools)
check-asan:
	@$(MAKE) --no-print-directory deps
	@$(MAKE) --no-print-directory -s all asan >$(ASAN_DIR).log 2>&1 || \
	    { cat $(ASAN_DIR).log; exit 1; }
	@sh tests/robust/check-asan.sh
	@$(MAKE) --no-print-directory check-valgrind
check-valgrind:
	@$(MAKE) --no-print-directory -s tools >/dev/null
	@sh tests/robust/valgrind.sh

FUZZ_DIR = build-fuzz
FUZZ_SECONDS ?= 300
fuzz:
	@$(MAKE) --no-print-directory deps
	@FUZZ_SECONDS=$(FUZZ_SECONDS) sh fuzz/run.sh

# grid convergence of the textures' flows (~40 minutes on 2 cores):
# tests/convergence/test_*.c, each run once
convergence.binaries = $(patsubst tests/convergence/%.c,$(BUILD)/convergence/%,\
    $(sort $(wildcard tests/convergence/test_*.c)))
$(BUILD)/convergence/%: tests/convergence/%.c $(wildcard tests/unit/*.h) $(core.lib)
	@mkdir -p $(dir $@)
	$(CORE_CC) $(CORE_CFLAGS) $< -o $@ $(TOOL_LIBS)
check-convergence:
	@$(MAKE) --no-print-directory deps
	@$(MAKE) --no-print-directory -s $(convergence.binaries) \
	    >$(BUILD).log 2>&1 || { cat $(BUILD).log; exit 1; }
	@sh tests/convergence/run.sh $(convergence.binaries)

check-long:
	@$(MAKE) --no-print-directory deps
	@$(MAKE) --no-print-directory -s all lib >$(BUILD).log 2>&1 || \
	    { cat $(BUILD).log; exit 1; }
	@sh tests/robust/long.sh

check-globals:
	@$(MAKE) --no-print-directory -s all lib >$(BUILD).log 2>&1 || \
	    { cat $(BUILD).log; exit 1; }
	@sh tests/robust/globals.sh

clean: clean-robust
clean-robust:
	rm -rf $(ASAN_DIR) $(ASAN_DIR).log $(FUZZ_DIR)
