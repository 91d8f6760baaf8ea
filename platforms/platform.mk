# aero: the library folder of one platform, ready to zip as a deken package
#   make -f platforms/platform.mk P=PLATFORM
# (the Makefile's `make platform P=PLATFORM` runs platforms/deps.sh, for
# Windows platforms/pd.sh, then this). PLATFORM is Pd's name:
#   linux-amd64    NAME.pd_linux (single: Pd 0.53 and 0.54+) and
#                  NAME.linux-amd64-64.so (double)
#   windows-amd64  NAME.windows-amd64-32.dll and NAME.windows-amd64-64.dll,
#                  and build/windows-amd64/aerotex.exe (and the tests'
#                  aero-analyze.exe) beside the folder
#   linux-arm64, linux-armv7
#                  NAME.pd_linux (single: Debian and Raspberry Pi OS ship
#                  Pd 0.53, which knows only .pd_linux)
#   darwin-arm64, darwin-amd64
#                  one macOS architecture (macOS 11 and later), binaries
#                  only: NAME.d_arm64 / NAME.d_amd64 (single) and
#                  NAME.darwin-arm64-64.so / NAME.darwin-amd64-64.so
#                  (double) in build/PLATFORM/aero/, and
#                  build/PLATFORM/aerotex; compiled by Zig's `zig cc`
#                  (platforms/zig.sh), linked by ld64.lld-14
#   darwin         the two joined into universal (fat) binaries by
#                  llvm-lipo: NAME.d_fat (single) and NAME.darwin-fat-64.so
#                  (double), and build/darwin/aerotex beside the folder
#                  (docs/building.md says why these names)
# Everything is compiled for the platform under build/PLATFORM/ (the core
# too), linked with the static FFTW and libsndfile of build/deps/PLATFORM,
# and exports only the Pd entry points (*_setup): hidden visibility and a
# version script on Linux, dllexport (AERO_PD_EXPORT, aero_pd.h) on
# Windows, ld64.lld's exported-symbols list on macOS. Pd's headers are Debian's (Pd 0.53: what they declare exists in
# every Pd the packages load in).
P ?= linux-amd64
.DEFAULT_GOAL := all
B = build/$(P)
STAGE = $(B)/aero
DEPS = build/deps/$(P)
PD_INCLUDE ?= /usr/include/pd

ifeq ($(P),darwin)
# --- macOS, universal: the two architectures' binaries joined -----------------
LIPO = llvm-lipo-14
EXT.32 = d_fat
EXT.64 = darwin-fat-64.so
classes = $(patsubst src/pd/%.c,%,$(sort $(wildcard src/pd/*~.c)))
externals.32 = $(patsubst %,$(STAGE)/%.$(EXT.32),$(classes) aero)
externals.64 = $(patsubst %,$(STAGE)/%.$(EXT.64),$(classes) aero)
TOOLS = $(B)/aerotex
$(STAGE)/%.d_fat: build/darwin-arm64/aero/%.d_arm64 build/darwin-amd64/aero/%.d_amd64
	@mkdir -p $(dir $@)
	$(LIPO) -create $^ -output $@
$(STAGE)/%.darwin-fat-64.so: build/darwin-arm64/aero/%.darwin-arm64-64.so \
    build/darwin-amd64/aero/%.darwin-amd64-64.so
	@mkdir -p $(dir $@)
	$(LIPO) -create $^ -output $@
$(B)/aerotex: build/darwin-arm64/aerotex build/darwin-amd64/aerotex
	@mkdir -p $(dir $@)
	$(LIPO) -create $^ -output $@
else ifneq ($(filter darwin-arm64 darwin-amd64,$(P)),)
# --- macOS, one architecture -------------------------------------------------
# Compiled by zig cc (platforms/zig.sh: clang 16 with the macOS 11 libc
# headers, no Apple SDK), linked by LLVM's Mach-O linker ld64.lld-14
# against Zig's copy of libSystem's interface (libSystem.11.tbd, install
# name /usr/lib/libSystem.B.dylib). Not Zig's own linker: Zig 0.11's
# exports every global symbol, hidden ones included (FFTW, libsndfile,
# compiler-rt: 840 names in one external). ld64.lld makes an MH_BUNDLE,
# the kind of file Pd's dlopen() expects of an external, exporting only
# the names of platforms/darwin/exports.txt (the *_setup functions), with
# Pd's functions left undefined and looked up in the flat namespace when
# Pd loads it (dynamic_lookup), and signs arm64 code ad hoc, as arm64
# macOS requires. -S: no debug map (it would name this machine's paths).
ZIG := $(shell sh platforms/zig.sh)
export ZIG_GLOBAL_CACHE_DIR ?= $(or $(AERO_CACHE),$(HOME)/.cache/aero)/zig-cache
ARCH = $(patsubst darwin-%,%,$(P))
ZIG_TARGET = $(if $(filter arm64,$(ARCH)),aarch64,x86_64)-macos.11.0
TARGET =
CC = $(ZIG) cc -target $(ZIG_TARGET)
AR = $(ZIG) ar --format=darwin
EXT.32 = d_$(ARCH)
EXT.64 = darwin-$(ARCH)-64.so
PD_IMPORT =
PIC = -fPIC
LD_ARCH = $(if $(filter arm64,$(ARCH)),arm64,x86_64)
LINK = ld64.lld-14 -arch $(LD_ARCH) -platform_version macos 11.0 11.0 -dead_strip -S
EXT_LDFLAGS = -bundle -undefined dynamic_lookup \
    -exported_symbols_list platforms/darwin/exports.txt
SYSLIBS = $(dir $(ZIG))lib/libc/darwin/libSystem.11.tbd
# aerotex without OpenMP: Zig has no OpenMP runtime for macOS; the pragmas
# are ignored and platforms/darwin/omp.h gives its lock and thread count
# calls for one thread
TOOL_CC = $(CC)
TOOL_OPENMP = -Iplatforms/darwin
TOOL_LDFLAGS =
TOOL_EXE =
TOOLS = $(B)/aerotex
DARWIN_THIN = yes
else ifeq ($(P),windows-amd64)
TARGET = x86_64-w64-mingw32-
EXT.32 = windows-amd64-32.dll
EXT.64 = windows-amd64-64.dll
# pd.dll's import library, from Pd 0.56-5 for Windows (platforms/pd.sh);
# single and double Pd export the same names from the same pd.dll
PD_IMPORT ?= build/pd-windows-amd64-single/bin/pd.dll.a
PIC =
# only the dllexport'ed setups leave a DLL (never GNU ld's export-all)
EXPORTS = -Wl,--exclude-all-symbols
# winpthreads (the core's field jobs) linked in: no libwinpthread-1.dll
SYSLIBS = -Wl,-Bstatic -lwinpthread -Wl,-Bdynamic -lm
# aerotex: OpenMP needs the POSIX-threads gcc; libgomp and winpthread
# linked in (-static): it runs with nothing but Windows' own DLLs
TOOL_CC = $(TARGET)gcc-posix
TOOL_LDFLAGS = -static
TOOL_EXE = .exe
TOOLS = $(B)/aerotex.exe $(B)/aero-analyze.exe
else
EXT.32 = pd_linux
EXT.64 = $(if $(filter linux-amd64,$(P)),linux-amd64-64.so)
PD_IMPORT =
PIC = -fPIC
EXPORTS = -Wl,--version-script=platforms/exports.map -Wl,--gc-sections
SYSLIBS = -lm -lpthread
ifeq ($(P),linux-amd64)
TARGET =
else ifeq ($(P),linux-arm64)
TARGET = aarch64-linux-gnu-
else ifeq ($(P),linux-armv7)
TARGET = arm-linux-gnueabihf-
else
$(error unknown platform '$(P)': linux-amd64 windows-amd64 linux-arm64 linux-armv7)
endif
TOOLS =
endif

ifeq ($(filter darwin%,$(P)),)
CC = $(TARGET)gcc
AR = $(TARGET)ar
endif
TOOL_OPENMP ?= -fopenmp
# as the native build (Makefile), plus hidden symbols; externals need
# OpenMP only for `omp simd` (-fopenmp-simd: no libgomp in them)
WARN = -Wall -Wextra -Wshadow
OPT = -O3 -funroll-loops -fomit-frame-pointer
CORE_INCLUDES = -Isrc/core/common -Isrc/core/solve -Isrc/core/play
BASE_CFLAGS = -std=c99 -D_POSIX_C_SOURCE=200809L $(OPT) $(WARN) $(PIC) \
    -fvisibility=hidden -ffunction-sections -fdata-sections \
    $(CORE_INCLUDES) -I$(DEPS)/include
CORE_CFLAGS = $(BASE_CFLAGS) -fopenmp-simd
PD_CFLAGS = $(BASE_CFLAGS) -DPD -I$(PD_INCLUDE) -Isrc/pd
LIBS = $(B)/libaero_core.a $(DEPS)/lib/libsndfile.a $(DEPS)/lib/libfftw3f.a \
    $(PD_IMPORT) $(SYSLIBS)
LINK ?= $(CC)
EXT_LDFLAGS ?= -shared $(EXPORTS)

# the same flow3d.c and rotor.c speed-up flags as the native build (Makefile)
$(B)/core/solve/flow3d.o $(B)/core-omp/solve/flow3d.o $(B)/core/play/rotor.o: \
    CORE_CFLAGS += -fno-trapping-math -fno-math-errno

core.sources = $(sort $(wildcard src/core/*/*.c))
core.objects = $(patsubst src/core/%.c,$(B)/core/%.o,$(core.sources))
core.headers = $(wildcard src/core/*/*.h)
# the core files with OpenMP threads (omp parallel): aerotex links these
# compiled with -fopenmp ahead of the archive
core.omp.sources = $(shell grep -l 'omp parallel' $(core.sources))
core.omp.objects = $(patsubst src/core/%.c,$(B)/core-omp/%.o,$(core.omp.sources))
classes = $(patsubst src/pd/%.c,%,$(sort $(wildcard src/pd/*~.c)))
pd.headers = src/pd/aero_pd.h src/pd/aero.h $(core.headers)

externals.32 = $(patsubst %,$(STAGE)/%.$(EXT.32),$(classes) aero)
externals.64 = $(if $(EXT.64),$(patsubst %,$(STAGE)/%.$(EXT.64),$(classes) aero))

# --- the staged folder: what pd-lib-builder's install puts there -------------
data = $(wildcard help/*.pd) $(wildcard abstractions/*.pd) \
    $(wildcard abstractions/*.blade) README.md LICENSE
staged.data = $(addprefix $(STAGE)/,$(notdir $(data)))
staged.dirs = $(wildcard textures/*.wav) $(wildcard trees/*.tree)
# the documents the README links to, at the same relative paths
staged.dirs += $(wildcard docs/*.md docs/img/*.png) textures/README.md \
    trees/README.md BENCHMARKS.md CONTRIBUTING.md
staged.files = $(addprefix $(STAGE)/,$(staged.dirs))

.PHONY: all
# a single macOS architecture: its binaries only (make P=darwin stages)
all: $(externals.32) $(externals.64) $(if $(DARWIN_THIN),,$(staged.data) $(staged.files)) $(TOOLS)
	@$(if $(filter no,$(CHECK_BINARIES)),true,sh platforms/check-binaries.sh $(P) $(externals.32) $(externals.64))
	@echo "$(STAGE): $(words $(externals.32) $(externals.64)) binaries$(if $(TOOLS), and $(TOOLS))"

$(STAGE)/%.pd: help/%.pd
	@mkdir -p $(dir $@)
	cp $< $@
$(STAGE)/%.pd: abstractions/%.pd
	@mkdir -p $(dir $@)
	cp $< $@
$(STAGE)/%.blade: abstractions/%.blade
	@mkdir -p $(dir $@)
	cp $< $@
$(STAGE)/%: %
	@mkdir -p $(dir $@)
	cp $< $@

# the universal macOS folder compiles nothing: its binaries come from the
# two architectures' builds (lipo, above)
ifneq ($(P),darwin)
# --- the core -----------------------------------------------------------------
$(B)/core/%.o: src/core/%.c $(core.headers)
	@mkdir -p $(dir $@)
	$(CC) $(CORE_CFLAGS) -c $< -o $@
$(B)/libaero_core.a: $(core.objects)
	rm -f $@
	$(AR) rcs $@ $^
$(B)/core-omp/%.o: src/core/%.c $(core.headers)
	@mkdir -p $(dir $@)
	$(TOOL_CC) $(CORE_CFLAGS) $(TOOL_OPENMP) -c $< -o $@

# --- the wrappers, single (32) and double (64) precision ----------------------
$(B)/pd32/%.o: src/pd/%.c $(pd.headers)
	@mkdir -p $(dir $@)
	$(CC) $(PD_CFLAGS) -c $< -o $@
$(B)/pd64/%.o: src/pd/%.c $(pd.headers)
	@mkdir -p $(dir $@)
	$(CC) $(PD_CFLAGS) -DPD_FLOATSIZE=64 -c $< -o $@

# one external per object; the single-binary library with every class
$(STAGE)/%.$(EXT.32): $(B)/pd32/%.o $(B)/pd32/aero_pd.o $(B)/libaero_core.a
	@mkdir -p $(dir $@)
	$(LINK) $(EXT_LDFLAGS) -o $@ $< $(B)/pd32/aero_pd.o $(LIBS)
$(STAGE)/aero.$(EXT.32): $(patsubst %,$(B)/pd32/%.o,aero aero_pd $(classes)) \
    $(B)/libaero_core.a
	@mkdir -p $(dir $@)
	$(LINK) $(EXT_LDFLAGS) -o $@ $(filter %.o,$^) $(LIBS)
ifneq ($(EXT.64),)
$(STAGE)/%.$(EXT.64): $(B)/pd64/%.o $(B)/pd64/aero_pd.o $(B)/libaero_core.a
	@mkdir -p $(dir $@)
	$(LINK) $(EXT_LDFLAGS) -o $@ $< $(B)/pd64/aero_pd.o $(LIBS)
$(STAGE)/aero.$(EXT.64): $(patsubst %,$(B)/pd64/%.o,aero aero_pd $(classes)) \
    $(B)/libaero_core.a
	@mkdir -p $(dir $@)
	$(LINK) $(EXT_LDFLAGS) -o $@ $(filter %.o,$^) $(LIBS)
endif

# --- aerotex (Windows, macOS): the texture precomputer, OpenMP inside ---------
aerotex.sources = $(sort $(wildcard src/tools/aerotex*.c))
TOOL_CFLAGS = $(filter-out -fvisibility=hidden,$(CORE_CFLAGS)) $(TOOL_OPENMP) \
    -DAEROTEX_NO_PNG
ifneq ($(DARWIN_THIN),)
# macOS: compiled by zig cc, linked by ld64.lld (above)
$(B)/tool/%.o: src/tools/%.c $(wildcard src/tools/*.h)
	@mkdir -p $(dir $@)
	$(TOOL_CC) $(TOOL_CFLAGS) -c $< -o $@
$(B)/aerotex: $(patsubst src/tools/%.c,$(B)/tool/%.o,$(aerotex.sources)) \
    $(core.omp.objects) $(B)/libaero_core.a
	$(LINK) -execute -o $@ $(filter %.o,$^) $(B)/libaero_core.a \
	    $(DEPS)/lib/libsndfile.a $(DEPS)/lib/libfftw3.a \
	    $(DEPS)/lib/libfftw3f.a $(SYSLIBS)
else
$(B)/aerotex$(TOOL_EXE): $(aerotex.sources) $(wildcard src/tools/*.h) \
    $(core.omp.objects) $(B)/libaero_core.a
	$(TOOL_CC) $(TOOL_CFLAGS) $(TOOL_LDFLAGS) $(aerotex.sources) \
	    $(core.omp.objects) -o $@ $(B)/libaero_core.a \
	    $(DEPS)/lib/libsndfile.a $(DEPS)/lib/libfftw3.a \
	    $(DEPS)/lib/libfftw3f.a -lm
endif

# the tests' analyser, for comparing renders on the platform itself
$(B)/aero-analyze$(TOOL_EXE): tests/analyze/aero-analyze.c $(B)/libaero_core.a
	$(TOOL_CC) $(filter-out $(TOOL_OPENMP) -DAEROTEX_NO_PNG,$(TOOL_CFLAGS)) \
	    $(TOOL_LDFLAGS) $< -o $@ $(B)/libaero_core.a \
	    $(DEPS)/lib/libsndfile.a $(DEPS)/lib/libfftw3.a -lm
endif
