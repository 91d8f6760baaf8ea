# aero: physically based aerodynamic sound for Pure Data.
#
#   make            externals (one per object), the core library, aerotex
#   make lib        the single-binary library aero.pd_linux (aero_setup())
#   make check      every test CI runs (installs missing dependencies first)
#   make check-unit the unit tests of src/core alone; ONLY=test_x picks
#                   binaries, CASE="a b" their cases (tests/unit/unit.h)
#   make check-pd056  the Pd tests again under Pd 0.56 (single and double
#                   precision, 48 kHz), built from ../shared/vendor
#   make double     the externals for double-precision Pd (*.linux-amd64-64.so)
#   make deken      deken packages (every platform, both float sizes,
#                   sources) in build/deken/
#   make check-packages  the packages' contents, and the Linux ones loaded
#                   and played in a minimal Debian with only Pd
#   make platform P=windows-amd64|linux-amd64|linux-arm64|linux-armv7|darwin
#                   the library folder for that platform in build/P/aero/,
#                   cross-compiled, FFTW and libsndfile linked statically
#                   (darwin: universal arm64 + x86_64 macOS binaries)
#   make check-macos  the macOS binaries' structure (Mach-O, exports,
#                   imports, signature, minos) and their compiler's code
#                   run on Linux against the gcc build
#   make check-gui  the help patches drawn by the Pd GUI (part of check)
#   make check-arm  aero's arm64 and armv7 packages in Pd under qemu-user
#   make check-libpd  aero inside libpd 0.16.1 (single, multi-instance,
#                   threads under helgrind); CI runs it after make check
#   make check-windows  aero's Windows package in Pd for Windows under wine
#   make demo       renders the demo scenes under build/demo/
#   make web        the web page (libpd + aero in WebAssembly) in build/web/;
#                   make web-serve, make check-web, make bench-web (below)
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

datafiles = $(wildcard help/*.pd) $(wildcard abstractions/*.pd) $(wildcard abstractions/*.blade) \
    README.md LICENSE
datadirs = $(if $(wildcard textures/*.wav),textures)
datadirs += $(if $(wildcard trees/*.tree),trees)

# No -ffast-math: the core relies on NaN checks (x != x) to sanitise input.
# -fvisibility=hidden: an external exports only Pd's entry points, marked
# AERO_PD_EXPORT (src/pd/aero_pd.h); tests/objects/96-exports.sh checks it.
CFLAGS = -Wall -Wextra -Wshadow -O3 -funroll-loops -fomit-frame-pointer \
    -fvisibility=hidden
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
    -fvisibility=hidden -Wall -Wextra -Wshadow $(CORE_INCLUDES)
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
# the same two for the rotor's self-noise envelope (rotor.c: its loop over
# the strips, with square roots and floors, vectorises only with both)
$(BUILD)/core/play/rotor.o: CORE_CFLAGS += -fno-trapping-math -fno-math-errno
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

# aerotex over MPI ranks (a task farm, src/tools/aerotex_farm.c;
# docs/cluster.md): build/aerotex-mpi, built beside the plain aerotex
# when Open MPI's compiler wrapper is found (MPI=0: never; MPI=1: always,
# failing without it). build/aerotex and the packages need nothing new.
MPICC ?= mpicc
MPI ?= $(if $(shell command -v $(MPICC) 2>/dev/null),1,0)
ifeq ($(MPI),1)
tools: $(BUILD)/aerotex-mpi $(BUILD)/tests/flow3d-slab
endif
$(BUILD)/aerotex-mpi: $(aerotex.sources) src/tools/flow3d_slab.c $(core.lib) \
    $(wildcard src/tools/*.h)
	OMPI_CC=$(CORE_CC) $(MPICC) $(CORE_CFLAGS) -DAEROTEX_MPI \
	    $(aerotex.sources) src/tools/flow3d_slab.c -o $@ -lfftw3f_mpi \
	    $(TOOL_LIBS)

# the 3D flow's projection in z slabs over MPI ranks against the
# one-process solver's (tests/objects/80-mpi.sh)
$(BUILD)/tests/flow3d-slab: tests/mpi/flow3d_slab.c src/tools/flow3d_slab.c \
    src/tools/flow3d_slab.h $(core.lib)
	@mkdir -p $(@D)
	OMPI_CC=$(CORE_CC) $(MPICC) $(CORE_CFLAGS) -Isrc/tools \
	    tests/mpi/flow3d_slab.c src/tools/flow3d_slab.c -o $@ \
	    -lfftw3f_mpi $(TOOL_LIBS)

$(BUILD)/aero-analyze: $(analyze.sources) $(core.lib)
	$(CORE_CC) $(CORE_CFLAGS) $(analyze.sources) -o $@ $(TOOL_LIBS)

# --- unit tests of src/core: one binary per tests/unit/test_*.c -------------
unit.sources = $(sort $(wildcard tests/unit/test_*.c))
unit.binaries = $(patsubst tests/unit/%.c,$(BUILD)/tests/%,$(unit.sources))

$(BUILD)/tests/%: tests/unit/%.c $(wildcard tests/unit/*.h) $(core.lib)
	@mkdir -p $(dir $@)
	$(CORE_CC) $(CORE_CFLAGS) $< -o $@ $(TOOL_LIBS)

# the unit tests alone (tests/unit/run.sh): make check-unit ONLY=cavity
# CASE=lock_in; each binary also runs alone (build/tests/test_x --list)
.PHONY: check-unit
check-unit:
	@$(MAKE) --no-print-directory -s tools >$(BUILD).log 2>&1 || \
	    { cat $(BUILD).log; exit 1; }
	@ONLY='$(ONLY)' CASE='$(CASE)' sh tests/unit/run.sh

# a maintainer's measure, not a check: the functions of src/ over LIMIT
# lines (default 80), longest first
.PHONY: long-functions
long-functions:
	@sh tests/long-functions.sh $(LIMIT)

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
# aerotex over MPI (build/aerotex-mpi, docs/cluster.md): Open MPI, and
# FFTW's MPI transforms
DEB_PACKAGES += libopenmpi-dev openmpi-bin libfftw3-mpi-dev
deps:
	@sh tests/deps.sh $(DEB_PACKAGES)
	@sh platforms/zig.sh >/dev/null 2>&1 || echo "aero: Zig for the macOS builds" \
	    "not installed (npm offline?): make platform P=darwin fetches it" >&2

# --- platforms: arm (linux-arm64, linux-armv7) under qemu-user ---------------
#   make check-arm  the staged arm packages (make platform P=linux-arm64,
#                   P=linux-armv7) in Pd 0.56-5 cross-built for each
#                   (platforms/pd.sh, cached) under qemu-user, by the shared
#                   platform runner (tests/platform/arm.sh -> run.sh)
# (the cross compilers: the platforms section below)
DEB_PACKAGES += qemu-user-static
ARM_PLATFORMS = linux-arm64 linux-armv7
.PHONY: check-arm
check-arm:
	@$(MAKE) --no-print-directory deps
	@$(MAKE) --no-print-directory -s all lib >$(BUILD).log 2>&1 || \
	    { cat $(BUILD).log; exit 1; }
	@mkdir -p $(BUILD) && for p in $(ARM_PLATFORMS); do \
	    $(MAKE) --no-print-directory -s platform P=$$p >$(BUILD)/platform-$$p.log 2>&1 || \
	    { cat $(BUILD)/platform-$$p.log; exit 1; }; done
	@sh tests/platform/arm.sh $(ARM_PLATFORMS)
# --- end of the arm section ---------------------------------------------------

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
# NAME[vVERSION](OS-CPU-FLOATSIZE).dek. `make deken` makes one package per
# platform and float size, zipped by platforms/deken.sh from the staged
# folders build/PLATFORM/aero/ (`make platform P=...`):
#   (Linux-amd64-32) *.pd_linux        (Linux-amd64-64) *.linux-amd64-64.so
#   (Linux-arm64-32) *.pd_linux        (Linux-armv7-32) *.pd_linux
#   (Windows-amd64-32) *.windows-amd64-32.dll
#   (Windows-amd64-64) *.windows-amd64-64.dll
#   (Darwin-arm64-32)(Darwin-amd64-32) *.d_fat
#   (Darwin-arm64-64)(Darwin-amd64-64) *.darwin-fat-64.so
# (macOS: one package for both CPUs, its binaries universal, one (ARCH) per
# CPU in the name as deken's filename format has it for such packages)
# and (Sources) (git archive of HEAD); each with its .dek.txt (the objects
# with the DESCRIPTION of their help patch's META) and .sha256.
# One package per platform, not one multi-platform ("fat") package, which
# deken also allows (several (ARCH) in one name): the arm and amd64 Linux
# binaries all have to be named *.pd_linux (Pd 0.53, the Pd of Debian and
# Raspberry Pi OS, knows no other Linux name), so they cannot share one
# folder; a user downloads only the binaries Pd can load (deken's plugin
# offers the packages of Pd's own platform and float size); and a platform
# that fails its check does not hold back the others.
# The version is the one of help/aero-meta.pd. (Debian's `deken` tool
# cannot run offline: it fetches its hy runtime from PyPI, so the archives
# are made here with zip, in the same format.)
#   make deken DEKEN_PLATFORMS=linux-amd64   only some platforms
#   make check-packages  every package's contents (tests/objects/96-packaging.sh)
#                   and the Linux ones in a minimal Debian 12 with only Pd
#                   (tests/packages/clean-debian.sh); run after the
#                   platform builds (make deken builds what is missing)
AERO_VERSION = $(shell sed -n 's/^\#X text [0-9]* [0-9]* VERSION \([0-9][0-9.]*\).*/\1/p' \
    help/aero-meta.pd | head -n 1)
DEKEN_DIR = $(BUILD)/deken
DEKEN_PLATFORMS ?= linux-amd64 linux-arm64 linux-armv7 windows-amd64 darwin
DEB_PACKAGES += unzip # the packaging test unpacks the .dek files
DEB_PACKAGES += debootstrap # the clean Debian of check-packages
deken:
	@test -n "$(AERO_VERSION)" || { echo "no VERSION in help/aero-meta.pd" >&2; exit 1; }
	rm -rf $(DEKEN_DIR)
	@for p in $(DEKEN_PLATFORMS); do \
	    $(MAKE) --no-print-directory platform P=$$p || exit 1; done
	sh platforms/deken.sh $(DEKEN_DIR) $(AERO_VERSION) $(DEKEN_PLATFORMS)

.PHONY: check-packages
check-packages:
	@$(MAKE) --no-print-directory deps
	@$(MAKE) --no-print-directory -s all lib double >$(BUILD).log 2>&1 || \
	    { cat $(BUILD).log; exit 1; }
	@sh tests/packages/check.sh

# --- libpd: aero linked into a host program -------------------------------
#   make libpd-example LIBPD_DIR=/path/to/libpd
# builds examples/libpd-host.c with every class and aero.c (one
# aero_setup()) against a built libpd: single-instance (`make STATIC=true`)
# or multi-instance (`make STATIC=true MULTI=true`), detected from the
# library (pd_this exists only in a multi-instance build; LIBPD_MULTI=yes|no
# overrides), linked statically with libs/libpd.a when it exists, else with
# libpd.so and an rpath (LIBPD_LINK=static|shared overrides). Against a
# shared single-instance libpd the wrappers must be position-independent
# (-fPIC): docs/libpd.md.
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

# --- platforms: Windows under wine (make check-windows) ----------------------
#   make check-windows  the staged Windows package (make platform
#                   P=windows-amd64) in Pd 0.56-5 for Windows (platforms/pd.sh,
#                   single and double precision, cached) under wine64 with an
#                   empty prefix in build/wine and no display, by the shared
#                   platform runner (tests/platform/check-windows.sh -> run.sh)
DEB_PACKAGES += wine64 gcc-mingw-w64-x86-64-win32 binutils-mingw-w64-x86-64
.PHONY: check-windows
check-windows:
	@$(MAKE) --no-print-directory deps
	@$(MAKE) --no-print-directory -s all lib double >$(BUILD).log 2>&1 || \
	    { cat $(BUILD).log; exit 1; }
	@echo "check-windows: the Windows package (log: $(BUILD)/windows-amd64.log)"
	@$(MAKE) --no-print-directory -s platform P=windows-amd64 \
	    >$(BUILD)/windows-amd64.log 2>&1 || \
	    { cat $(BUILD)/windows-amd64.log; exit 1; }
	@sh tests/platform/check-windows.sh
# --- end of the Windows section ----------------------------------------------

# ============================================================================
# --- robustness: sanitizers, fuzzing, long runs, globals --------
#   make check-asan   unit tests + Pd batch tests under ASan/UBSan (gcc),
#                     instrumented externals loaded into Pd with libasan
#                     preloaded, and check-valgrind beside it (2 cores)
#   make check-valgrind  the core unit tests under valgrind memcheck, but
#                     those declared slow (tests/robust/slow-tests.sh)
#   ONLY=pattern      scopes both, as in tests/run.sh (ONLY=aeolian)
#   make fuzz         libFuzzer harnesses fuzz/fuzz_*.c (FUZZ_SECONDS
#                     per harness, default 300)
#   make check-long   one hour of audio per long run of tests/robust/objects/
#   make check-globals  no writable globals in src/ (nm)
# Everything builds under build-asan/ and build-fuzz/; build/ is untouched.
# ============================================================================
DEB_PACKAGES += clang libclang-rt-14-dev
ASAN_DIR = build-asan
ASAN_CC = gcc
# float-cast-overflow is not part of gcc's 'undefined': (int) of a NaN or
# huge float from a patch is exactly what hostile input produces. The cost
# (test_cavity_flow, one thread, CPU): 3.2 s built -O3, 47 s instrumented
# at -O1, 41 s at -O2; most of it is UBSan's checks in the solver loops
# (UBSan alone at -O1: 33 s; -O1 alone: 9 s). -O2 keeps -g's lines.
ASAN_FLAGS = -g -O2 -fno-omit-frame-pointer -fsanitize=address,undefined \
    -fsanitize=float-cast-overflow -fno-sanitize-recover=undefined,float-cast-overflow
# -fvisibility=hidden as in the real build (96-exports.sh checks the
# instrumented externals too)
ASAN_CFLAGS = -std=c99 -D_POSIX_C_SOURCE=200809L -fPIC -fopenmp \
    -fvisibility=hidden -Wall -Wextra -Wshadow $(CORE_INCLUDES) $(ASAN_FLAGS)
ASAN_ROOT = $(ASAN_DIR)/root
asan.core.objects = $(patsubst src/core/%.c,$(ASAN_DIR)/core/%.o,$(core.sources))
asan.lib = $(ASAN_DIR)/libaero_core.a
asan.externals = $(patsubst src/pd/%.c,$(ASAN_ROOT)/%.pd_linux,$(class.sources))
asan.tools = $(ASAN_ROOT)/build/aerotex $(ASAN_ROOT)/build/aero-analyze \
    $(patsubst tests/unit/%.c,$(ASAN_ROOT)/build/tests/%,$(unit.sources))
ASAN_PD_CFLAGS = -DPD -DUNIX -I/usr/include/pd -shared $(ASAN_CFLAGS)
# every instrumented file depends on the flags it was built with: a change
# of ASAN_FLAGS rebuilds them
asan.flags = $(ASAN_DIR)/flags
$(asan.flags): asan-flags-stamp
	@mkdir -p $(dir $@)
	@echo '$(ASAN_PD_CFLAGS)' | cmp -s - $@ || echo '$(ASAN_PD_CFLAGS)' >$@
.PHONY: asan-flags-stamp

$(ASAN_DIR)/core/%.o: src/core/%.c $(wildcard src/core/*/*.h) $(asan.flags)
	@mkdir -p $(dir $@)
	$(ASAN_CC) $(ASAN_CFLAGS) -c $< -o $@
$(asan.lib): $(asan.core.objects)
	rm -f $@; ar rcs $@ $^
$(ASAN_ROOT)/%~.pd_linux: src/pd/%~.c $(common.sources) src/pd/aero_pd.h $(asan.lib) $(asan.flags)
	@mkdir -p $(dir $@)
	$(ASAN_CC) $(ASAN_PD_CFLAGS) $< $(common.sources) -o $@ $(asan.lib) \
	    -lsndfile -lfftw3f_threads -lfftw3f -lm
$(ASAN_ROOT)/aero.pd_linux: $(lib.setup.sources) $(class.sources) $(common.sources) $(asan.lib)
	$(ASAN_CC) $(ASAN_PD_CFLAGS) $(lib.setup.sources) $(class.sources) $(common.sources) -o $@ \
	    $(asan.lib) -lsndfile -lfftw3f_threads -lfftw3f -lm
$(ASAN_ROOT)/build/aerotex: $(aerotex.sources) $(asan.lib) $(asan.flags)
	@mkdir -p $(dir $@)
	$(ASAN_CC) $(ASAN_CFLAGS) $(aerotex.sources) -o $@ \
	    $(subst $(core.lib),$(asan.lib),$(TOOL_LIBS))
$(ASAN_ROOT)/build/aero-analyze: $(analyze.sources) $(asan.lib) $(asan.flags)
	@mkdir -p $(dir $@)
	$(ASAN_CC) $(ASAN_CFLAGS) $(analyze.sources) -o $@ \
	    $(subst $(core.lib),$(asan.lib),$(TOOL_LIBS))
$(ASAN_ROOT)/build/tests/%: tests/unit/%.c $(wildcard tests/unit/*.h) $(asan.lib) $(asan.flags)
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
	@$(MAKE) --no-print-directory -s tools >/dev/null
	@# check-valgrind runs beside the ASan suite (one core each); its
	@# report follows the suite's
	@$(MAKE) --no-print-directory check-valgrind >$(ASAN_DIR)/valgrind.log 2>&1 & \
	    sh tests/robust/check-asan.sh; asan=$$?; wait $$!; valgrind=$$?; \
	    echo; cat $(ASAN_DIR)/valgrind.log; \
	    [ $$asan -eq 0 ] && [ $$valgrind -eq 0 ]
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

# ============================================================================
# --- platforms: cross builds, the staged library folder per platform --------
#   make platform P=PLATFORM   build/PLATFORM/aero/: every external, the
#                  single-binary library, help, abstractions, textures,
#                  trees, meta, LICENSE, README (a deken package's folder);
#                  PLATFORM is linux-amd64, windows-amd64, linux-arm64,
#                  linux-armv7 or darwin (macOS, universal; darwin-arm64 and
#                  darwin-amd64 are its two halves, binaries only)
#                  (platforms/platform.mk says what each holds)
#   make windows | linux-amd64 | linux-arm64 | linux-armv7 | darwin   the same
# FFTW and libsndfile are linked statically, built once per machine by
# platforms/deps.sh (cached in ${AERO_CACHE:-~/.cache/aero}); the Windows
# externals link pd.dll's import library from Pd for Windows
# (platforms/pd.sh, cached the same way).
# ============================================================================
PLATFORMS = linux-amd64 windows-amd64 linux-arm64 linux-armv7 darwin \
    darwin-arm64 darwin-amd64
DEB_PACKAGES += gcc-mingw-w64-x86-64-win32 gcc-mingw-w64-x86-64-posix \
    gcc-aarch64-linux-gnu libc6-dev-arm64-cross \
    gcc-arm-linux-gnueabihf libc6-dev-armhf-cross
.PHONY: platform platforms windows linux-amd64 linux-arm64 linux-armv7 darwin
platform:
	@case " $(PLATFORMS) " in *" $(P) "*) ;; *) \
	    echo "make platform P=PLATFORM, one of: $(PLATFORMS)" >&2; exit 2 ;; esac
	@$(if $(filter darwin,$(P)),for a in arm64 amd64; do \
	    $(MAKE) --no-print-directory platform P=darwin-$$a || exit 1; done,\
	    $(MAKE) --no-print-directory -s $(VENDORED)/fftw-3.3.10.tar.gz \
	        $(VENDORED)/libsndfile-1.2.0.tar.gz && \
	    AERO_VENDOR=$(abspath $(VENDORED)) sh platforms/deps.sh $(P))
	@$(if $(filter windows-%,$(P)),sh platforms/pd.sh $(P) single >/dev/null)
	@$(MAKE) --no-print-directory -f platforms/platform.mk P=$(P)
windows:
	@$(MAKE) --no-print-directory platform P=windows-amd64
linux-amd64 linux-arm64 linux-armv7 darwin:
	@$(MAKE) --no-print-directory platform P=$@
platforms:
	@for p in $(filter-out darwin-%,$(PLATFORMS)); do \
	    $(MAKE) --no-print-directory platform P=$$p || exit 1; done

# --- macOS: universal arm64 + x86_64 binaries, built and checked here ------
#   make platform P=darwin  (above) build/darwin/aero/: NAME.d_fat and
#                   NAME.darwin-fat-64.so, and build/darwin/aerotex;
#                   Zig 0.11's zig cc (platforms/zig.sh, from npm, cached),
#                   linked by LLVM's ld64.lld
#   make check-macos  tests/macos/check.sh: every binary's Mach-O structure,
#                   exports, imports, libraries, minos and arm64 signature
#                   read with LLVM's tools, and the same compiler's code
#                   run on Linux (unit tests, the platform runner against
#                   the gcc build). No macOS runs here.
DEB_PACKAGES += llvm-14 lld-14
.PHONY: check-macos
check-macos:
	@$(MAKE) --no-print-directory deps
	@$(MAKE) --no-print-directory -s all lib >$(BUILD).log 2>&1 || \
	    { cat $(BUILD).log; exit 1; }
	@mkdir -p $(BUILD) && $(MAKE) --no-print-directory -s platform P=darwin \
	    >$(BUILD)/platform-darwin.log 2>&1 || { cat $(BUILD)/platform-darwin.log; exit 1; }
	@sh tests/macos/check.sh

# --- web: aero in the browser (libpd + aero compiled to WebAssembly) --------
#   make web        build/web/: the page of web/, libpd 0.16.1 (Pd 0.56-5)
#                   with aero linked in (one aero_setup()) as aero.wasm +
#                   its ES module aero.js, FFTW and libsndfile for wasm
#                   (platforms/deps.sh wasm, cached), the scene patches,
#                   abstractions, textures and trees the page loads into
#                   the module's file system
#   make web-serve  serves build/web/ on http://127.0.0.1:8000/ (PORT=)
#   make check-web  the page in headless Chromium against native renders
#                   (tests/web/run.sh)
# Debian's emscripten works offline from its own cache (EM_CACHE unset);
# its tools run under this Node with Debian's node modules.
DEB_PACKAGES += emscripten chromium nodejs
# npm: Debian's package, unless a node that brings its own npm (NodeSource's,
# which conflicts with Debian's npm) is installed
DEB_PACKAGES += $(if $(shell command -v npm),,npm)
WEB = $(BUILD)/web
# where the outside source archives are looked for first; missing ones are
# fetched and every one is checked (platforms/vendor.sh, docs/building.md)
VENDOR ?= ../shared/vendor
EMCC = NODE_PATH=/usr/share/nodejs nice -n 10 emcc
EMAR = NODE_PATH=/usr/share/nodejs emar
WASM_DEPS = $(BUILD)/deps/wasm
WASM_LIBPD = $(BUILD)/libpd/wasm
# the core as for the native build, without OpenMP (its pragmas only
# parallelise the texture solvers, which a page does not run)
WASM_CFLAGS = -std=c99 -D_POSIX_C_SOURCE=200809L -O3 -Wall -Wextra -Wshadow \
    -Wno-unknown-pragmas $(CORE_INCLUDES) -I$(WASM_DEPS)/include
wasm.core.objects = $(patsubst src/core/%.c,$(BUILD)/wasm/core/%.o,$(core.sources))
wasm.core.lib = $(BUILD)/wasm/libaero_core.a
WASM_EXPORTS = _aero_web_init,_aero_web_open,_aero_web_close,_aero_web_process,$\
    _libpd_start_message,_libpd_add_float,_libpd_add_symbol,$\
    _libpd_finish_message,_libpd_finish_list,_libpd_bang,_libpd_float,$\
    _malloc,_free
WASM_LDFLAGS = -O3 -sMODULARIZE=1 -sEXPORT_ES6=1 -sEXPORT_NAME=createAero \
    -sENVIRONMENT=web -sALLOW_MEMORY_GROWTH=1 -sINITIAL_MEMORY=33554432 \
    -sFORCE_FILESYSTEM=1 -sEXPORTED_RUNTIME_METHODS=FS,ccall,cwrap \
    -sEXPORTED_FUNCTIONS=$(WASM_EXPORTS)
# the data the scenes load (web/scenes.js lists each scene's), no more
web.textures = textures/sword.wav textures/cylinder.wav textures/sphere.wav \
    textures/fire.wav
web.trees = trees/medium.tree
# the blade tables aero.propeller~ and aero.turbine~ read beside themselves
web.blades = $(wildcard abstractions/*.blade)
web.data = $(wildcard web/scenes/*.pd) $(wildcard abstractions/*.pd) \
    $(web.blades) $(web.textures) $(web.trees)
web.page = $(wildcard web/*.html web/*.js web/*.css)

# platforms/deps.sh wasm: links in build/deps/wasm to the cached libraries
# (whose times are the cache's: a stamp says when they were linked)
WASM_DEPS_STAMP = $(WASM_DEPS)/.linked
# build/vendor/: links to the archives as platforms/vendor.sh finds or
# fetches them, each checked against its pinned SHA-256 when linked (make
# reads a link's time as its archive's: they are order-only prerequisites,
# so that an archive's date never rebuilds what it built)
VENDORED = $(BUILD)/vendor
$(VENDORED)/%.tar.gz:
	@mkdir -p $(dir $@)
	a=$$(VENDOR=$(abspath $(VENDOR)) sh platforms/vendor.sh $*.tar.gz) && \
	    ln -sf "$$a" $@
$(WASM_DEPS_STAMP): platforms/deps.sh platforms/deps/fftw.sh platforms/deps/sndfile.sh \
    | $(VENDORED)/fftw-3.3.10.tar.gz $(VENDORED)/libsndfile-1.2.0.tar.gz
	NODE_PATH=/usr/share/nodejs AERO_VENDOR=$(abspath $(VENDORED)) \
	    nice -n 10 sh platforms/deps.sh wasm
	touch $@

# libpd's own Makefile with emcc: the static library only, no extras (pd~
# forks), no utils
$(WASM_LIBPD)/libs/libpd.a: | $(VENDORED)/libpd-0.16.1.tar.gz \
    $(VENDORED)/pure-data-0.56-5.tar.gz
	rm -rf $(WASM_LIBPD) && mkdir -p $(WASM_LIBPD)/pure-data
	tar xzf $(VENDORED)/libpd-0.16.1.tar.gz -C $(WASM_LIBPD) --strip-components=1
	tar xzf $(VENDORED)/pure-data-0.56-5.tar.gz -C $(WASM_LIBPD)/pure-data \
	    --strip-components=1
	env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL NODE_PATH=/usr/share/nodejs \
	    nice -n 10 make -C $(WASM_LIBPD) -j2 CC=emcc AR=emar STATIC=true \
	    EXTRA=false UTIL=false libs/libpd.a >$(WASM_LIBPD).log 2>&1 || \
	    { tail -20 $(WASM_LIBPD).log; exit 1; }
	# libpd's Makefile archives with the host's ar: the index for wasm-ld
	NODE_PATH=/usr/share/nodejs emranlib $@

$(BUILD)/wasm/core/%.o: src/core/%.c $(wildcard src/core/*/*.h) \
    $(WASM_DEPS_STAMP)
	@mkdir -p $(dir $@)
	$(EMCC) $(WASM_CFLAGS) -c $< -o $@

$(wasm.core.lib): $(wasm.core.objects)
	rm -f $@
	$(EMAR) rcs $@ $^

$(WEB)/aero.js: web/aero_web.c $(class.sources) $(lib.setup.sources) \
    $(common.sources) src/pd/aero_pd.h $(wasm.core.lib) \
    $(WASM_LIBPD)/libs/libpd.a $(WASM_DEPS_STAMP)
	@mkdir -p $(WEB)
	$(EMCC) -std=c99 -D_POSIX_C_SOURCE=200809L -Wall -Wextra \
	    -Wno-unknown-pragmas -DHAVE_LIBPD -I$(WASM_LIBPD)/libpd_wrapper \
	    -I$(WASM_LIBPD)/pure-data/src -Isrc/pd $(CORE_INCLUDES) \
	    -I$(WASM_DEPS)/include web/aero_web.c $(class.sources) \
	    $(lib.setup.sources) $(common.sources) $(wasm.core.lib) \
	    $(WASM_LIBPD)/libs/libpd.a $(WASM_DEPS)/lib/libsndfile.a \
	    $(WASM_DEPS)/lib/libfftw3f.a $(WASM_LDFLAGS) -o $@

.PHONY: web web-serve check-web bench-web
web: $(WEB)/aero.js $(web.data) $(web.page)
	@mkdir -p $(WEB)/aero/scenes $(WEB)/aero/abstractions \
	    $(WEB)/aero/textures $(WEB)/aero/trees
	cp $(web.page) $(WEB)/
	cp web/scenes/*.pd $(WEB)/aero/scenes/
	cp abstractions/*.pd $(web.blades) $(WEB)/aero/abstractions/
	cp $(web.textures) $(WEB)/aero/textures/
	cp $(web.trees) $(WEB)/aero/trees/
	@echo "web: $(WEB)/ (make web-serve, then open http://127.0.0.1:$(PORT)/)"

# on this machine only (127.0.0.1), on port PORT (make web-serve PORT=8080)
PORT ?= 8000
web-serve: web
	python3 -m http.server $(PORT) --bind 127.0.0.1 --directory $(WEB)

# only what it uses natively: the core for the native host, the analyser
check-web:
	@$(MAKE) --no-print-directory deps
	@$(MAKE) --no-print-directory -s -j2 $(core.lib) $(BUILD)/aero-analyze web \
	    >$(BUILD).log 2>&1 || { cat $(BUILD).log; exit 1; }
	@sh tests/web/run.sh

bench-web: web
	@test -x $(BUILD)/web-check/render-native || $(MAKE) --no-print-directory check-web
	@sh bench/web.sh
