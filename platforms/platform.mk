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
# Everything is compiled for the platform under build/PLATFORM/ (the core
# too), linked with the static FFTW and libsndfile of build/deps/PLATFORM,
# and exports only the Pd entry points (*_setup): hidden visibility and a
# version script on Linux, dllexport (AERO_PD_EXPORT, aero_pd.h) on
# Windows. Pd's headers are Debian's (Pd 0.53: what they declare exists in
# every Pd the packages load in).
P ?= linux-amd64
B = build/$(P)
STAGE = $(B)/aero
DEPS = build/deps/$(P)
PD_INCLUDE ?= /usr/include/pd

ifeq ($(P),windows-amd64)
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

CC = $(TARGET)gcc
AR = $(TARGET)ar
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
LDFLAGS = -shared $(EXPORTS)

# the same flow3d.c speed-up flags as the native build (Makefile)
$(B)/core/solve/flow3d.o $(B)/core-omp/solve/flow3d.o: \
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
data = $(wildcard help/*.pd) $(wildcard abstractions/*.pd) README.md LICENSE
staged.data = $(addprefix $(STAGE)/,$(notdir $(data)))
staged.dirs = $(wildcard textures/*.wav) $(wildcard trees/*.tree)
# the documents the README links to, at the same relative paths
staged.dirs += $(wildcard docs/*.md docs/img/*.png) textures/README.md \
    trees/README.md BENCHMARKS.md CONTRIBUTING.md
staged.files = $(addprefix $(STAGE)/,$(staged.dirs))

.PHONY: all
all: $(externals.32) $(externals.64) $(staged.data) $(staged.files) $(TOOLS)
	@sh platforms/check-binaries.sh $(P) $(externals.32) $(externals.64)
	@echo "$(STAGE): $(words $(externals.32) $(externals.64)) binaries$(if $(TOOLS), and $(TOOLS))"

$(STAGE)/%.pd: help/%.pd
	@mkdir -p $(dir $@)
	cp $< $@
$(STAGE)/%.pd: abstractions/%.pd
	@mkdir -p $(dir $@)
	cp $< $@
$(STAGE)/%: %
	@mkdir -p $(dir $@)
	cp $< $@

# --- the core -----------------------------------------------------------------
$(B)/core/%.o: src/core/%.c $(core.headers)
	@mkdir -p $(dir $@)
	$(CC) $(CORE_CFLAGS) -c $< -o $@
$(B)/libaero_core.a: $(core.objects)
	rm -f $@
	$(AR) rcs $@ $^
$(B)/core-omp/%.o: src/core/%.c $(core.headers)
	@mkdir -p $(dir $@)
	$(TOOL_CC) $(CORE_CFLAGS) -fopenmp -c $< -o $@

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
	$(CC) $(LDFLAGS) -o $@ $< $(B)/pd32/aero_pd.o $(LIBS)
$(STAGE)/aero.$(EXT.32): $(patsubst %,$(B)/pd32/%.o,aero aero_pd $(classes)) \
    $(B)/libaero_core.a
	@mkdir -p $(dir $@)
	$(CC) $(LDFLAGS) -o $@ $(filter %.o,$^) $(LIBS)
ifneq ($(EXT.64),)
$(STAGE)/%.$(EXT.64): $(B)/pd64/%.o $(B)/pd64/aero_pd.o $(B)/libaero_core.a
	@mkdir -p $(dir $@)
	$(CC) $(LDFLAGS) -o $@ $< $(B)/pd64/aero_pd.o $(LIBS)
$(STAGE)/aero.$(EXT.64): $(patsubst %,$(B)/pd64/%.o,aero aero_pd $(classes)) \
    $(B)/libaero_core.a
	@mkdir -p $(dir $@)
	$(CC) $(LDFLAGS) -o $@ $(filter %.o,$^) $(LIBS)
endif

# --- aerotex (Windows): the texture precomputer, OpenMP inside ---------------
aerotex.sources = $(sort $(wildcard src/tools/aerotex*.c))
TOOL_CFLAGS = $(filter-out -fvisibility=hidden,$(CORE_CFLAGS)) -fopenmp \
    -DAEROTEX_NO_PNG
$(B)/aerotex$(TOOL_EXE): $(aerotex.sources) $(wildcard src/tools/*.h) \
    $(core.omp.objects) $(B)/libaero_core.a
	$(TOOL_CC) $(TOOL_CFLAGS) $(TOOL_LDFLAGS) $(aerotex.sources) \
	    $(core.omp.objects) -o $@ $(B)/libaero_core.a \
	    $(DEPS)/lib/libsndfile.a $(DEPS)/lib/libfftw3.a \
	    $(DEPS)/lib/libfftw3f.a -lm

# the tests' analyser, for comparing renders on the platform itself
$(B)/aero-analyze$(TOOL_EXE): tests/analyze/aero-analyze.c $(B)/libaero_core.a
	$(TOOL_CC) $(filter-out -fopenmp -DAEROTEX_NO_PNG,$(TOOL_CFLAGS)) \
	    $(TOOL_LDFLAGS) $< -o $@ $(B)/libaero_core.a \
	    $(DEPS)/lib/libsndfile.a $(DEPS)/lib/libfftw3.a -lm
