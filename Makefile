# gravel - DEM engine. `make` builds bin/gravel; `make test` and `make run`
# first make sure the Debian packages it needs are installed (`make deps`).

CC      ?= gcc
CFLAGS  ?= -O2 -g
WARN     = -Wall -Wextra -Werror
# every folder of src/ and styles/ is on the include path (doc/architecture.md)
SRCDIRS  = $(sort $(dir $(wildcard src/*/*.c src/*/*.h styles/*/*.c styles/*/*.h)))
CPPFLAGS = -std=c11 -D_GNU_SOURCE -D_FILE_OFFSET_BITS=64 $(patsubst %/,-I%,$(SRCDIRS)) -Istyles -Ikernels \
           -Ibuild/gen
LDLIBS   = -lOpenCL -lgsl -lgslcblas -lm
SANFLAGS = -O1 -g -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined

SRC      = $(wildcard src/*/*.c styles/*/*.c)
LIBSRC   = $(filter-out src/core/main.c,$(SRC))
OBJ      = $(SRC:%.c=build/obj/%.o) build/obj/kernels.o
LIBOBJ   = $(LIBSRC:%.c=build/obj/%.o) build/obj/kernels.o
ASANOBJ  = $(LIBSRC:%.c=build/asan/%.o) build/asan/kernels.o
KERNELS  = $(sort $(wildcard kernels/*.cl kernels/*.h))
UNITSRC  = $(wildcard tests/unit/test_*.c)
UNITBIN  = $(UNITSRC:tests/unit/%.c=build/tests/%)
# the builds that make test, run and bench start use every core (2: 57 s instead of 96)
JOBS    := $(shell nproc 2> /dev/null || echo 1)

.PHONY: all deps test run bench bench-all clean asan fuzz fuzz-replay fuzz-merge verify reproduce-agglomeration reproduce-mill mill-sensitivity compare-avalanche
all: bin/gravel

bin/gravel: $(OBJ)
	@mkdir -p bin
	$(CC) $(CFLAGS) -o $@ $^ $(LDLIBS)

# bin/gravel-mpi: the same engine over MPI ranks (doc/parallel.md), built when
# mpicc is installed (Debian libopenmpi-dev). Only src/parallel/comm.c differs:
# it is compiled again with GR_MPI.
MPICC  ?= $(shell command -v mpicc 2>/dev/null)
MPIOBJ  = $(filter-out build/obj/src/parallel/comm.o,$(OBJ)) build/mpi/comm.o
ifneq ($(MPICC),)
all: bin/gravel-mpi
endif
bin/gravel-mpi: $(MPIOBJ)
	@mkdir -p bin
	$(MPICC) $(CFLAGS) -o $@ $^ $(LDLIBS)
build/mpi/comm.o: src/parallel/comm.c src/parallel/comm.h
	@mkdir -p build/mpi
	$(MPICC) $(CPPFLAGS) -DGR_MPI $(CFLAGS) $(WARN) -c -o $@ $<

# Sanitizer build of the whole engine, used by the unit tests and the fuzz replay.
asan: bin/gravel-asan $(UNITBIN)
bin/gravel-asan: $(ASANOBJ) build/asan/src/core/main.o
	@mkdir -p bin
	$(CC) $(SANFLAGS) -o $@ $^ $(LDLIBS)

build/obj/%.o: %.c $(wildcard src/*/*.h styles/*/*.h kernels/*.h) src/script/commands.def styles/styles.def
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS) $(WARN) -c -o $@ $<

build/asan/%.o: %.c $(wildcard src/*/*.h styles/*/*.h kernels/*.h) src/script/commands.def styles/styles.def
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(SANFLAGS) $(WARN) -c -o $@ $<

# Kernel sources are embedded in the binary: it runs from any directory.
build/gen/kernels.c: $(KERNELS) tools/embed.c
	@mkdir -p build/gen
	$(CC) -O1 -o build/gen/embed tools/embed.c
	build/gen/embed $(KERNELS) > $@
build/obj/kernels.o: build/gen/kernels.c
	$(CC) $(CPPFLAGS) $(CFLAGS) -c -o $@ $<
build/asan/kernels.o: build/gen/kernels.c
	@mkdir -p build/asan
	$(CC) $(CPPFLAGS) $(SANFLAGS) -c -o $@ $<

build/tests/%: tests/unit/%.c tests/unit/test.h $(ASANOBJ)
	@mkdir -p build/tests
	$(CC) $(CPPFLAGS) $(SANFLAGS) $(WARN) -Itests/unit -o $@ $< $(ASANOBJ) $(LDLIBS)

deps:
	@sh tools/deps.sh

test: deps
	@$(MAKE) --no-print-directory -j$(JOBS) all asan
	@sh tests/run.sh

run: deps
	@$(MAKE) --no-print-directory -j$(JOBS) all
	cd inputs/examples && ../../bin/gravel -in settle.in

bench: deps
	@$(MAKE) --no-print-directory -j$(JOBS) all
	@sh tools/bench.sh

# bench and issue 19's other figures: mesh against pair contacts (three laws) and 10^7 spheres
bench-all: bench
	@/usr/bin/python3 tools/bench_mesh.py --repeat 3 --law hooke/history
	@/usr/bin/python3 tools/bench_mesh.py --repeat 3 --law hertz/mindlin
	@/usr/bin/python3 tools/bench_mesh.py --repeat 3 --law linear/restitution
	@sh tools/bench_big.sh

# Log regression (tests/regression/, doc/regression.md): every deck in inputs/
# runs shortened and its thermo log is compared with the committed reference
# by tools/logcompare. regress-update rewrites the references for review in
# the diff (LAMMPS=1 also reruns the LAMMPS references with lmp).
.PHONY: regress regress-update
regress: all
	@/usr/bin/python3 tests/regression/regress.py
regress-update: all
	@/usr/bin/python3 tests/regression/regress.py --update $(if $(LAMMPS),--lammps)

# Verification report: runs inputs/verification/ at t_col/8 ... /128 in both
# precisions and writes doc/verification.md + doc/verification/*.png (gnuplot).
verify: deps
	@sh tools/deps.sh gnuplot-nox
	@$(MAKE) --no-print-directory all
	/usr/bin/python3 tools/verify_doc.py

# libFuzzer target for the interpreter (clang; the harness works in a scratch
# directory, so its paths are absolute). `make fuzz FUZZ_TIME=600` runs it
# for that many seconds on one core, niced; new inputs go to build/fuzz/corpus,
# the committed seeds stay in tests/fuzz/corpus. `make fuzz-replay` runs every
# committed corpus file through the ASan build (also part of make test), and
# `make fuzz-merge` adds the new inputs that reach new edges to tests/fuzz/found.
FUZZ_TIME ?= 60
FUZZ_TIMEOUT ?= 10
FUZZFLAGS = -O1 -g -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined
FUZZOBJ   = $(LIBSRC:%.c=build/fuzz/%.o) build/fuzz/kernels.o
build/fuzz/%.o: %.c $(wildcard src/*/*.h styles/*/*.h kernels/*.h) src/script/commands.def styles/styles.def
	@mkdir -p $(dir $@)
	clang $(CPPFLAGS) $(FUZZFLAGS) -fsanitize=fuzzer-no-link -c -o $@ $<
build/fuzz/kernels.o: build/gen/kernels.c
	@mkdir -p build/fuzz
	clang $(CPPFLAGS) $(FUZZFLAGS) -c -o $@ $<
bin/fuzz_input: tests/fuzz/fuzz_input.c $(FUZZOBJ)
	@mkdir -p bin
	clang $(CPPFLAGS) $(FUZZFLAGS) -fsanitize=fuzzer -o $@ $^ $(LDLIBS)
fuzz: bin/fuzz_input
	@mkdir -p build/fuzz/corpus build/fuzz/crashes
	nice -n 19 bin/fuzz_input -max_len=1200000 -max_total_time=$(FUZZ_TIME) -timeout=$(FUZZ_TIMEOUT) \
	    -rss_limit_mb=2048 -artifact_prefix=$(CURDIR)/build/fuzz/crashes/ \
	    -dict=$(CURDIR)/tests/fuzz/gravel.dict $(CURDIR)/build/fuzz/corpus $(CURDIR)/tests/fuzz/corpus
fuzz-replay: bin/gravel-asan build/tests/test_fuzz_corpus
	@sh tests/scripts/fuzz_replay.sh
	@build/tests/test_fuzz_corpus
# Add the inputs of build/fuzz/corpus that reach new edges to the committed
# replay set tests/fuzz/found (replayed in process by test_fuzz_corpus).
fuzz-merge: bin/fuzz_input
	@mkdir -p tests/fuzz/found
	$(CURDIR)/bin/fuzz_input -merge=1 -use_counters=0 -timeout=30 -rss_limit_mb=2048 \
	    $(CURDIR)/tests/fuzz/found $(CURDIR)/build/fuzz/corpus

# The agglomeration study of source document 000 chapter 6 (fig. 6.8), see
# doc/agglomeration.md: about 2 h with the defaults (N 1000, 300 s); AGGLO_QUICK=1 for a few minutes.
# Checkpoints with restart files: run it again after an interruption and it resumes.
reproduce-agglomeration: deps
	@sh tools/deps.sh gnuplot-nox
	@$(MAKE) --no-print-directory all
	@sh tools/agglomeration/sweep.sh

# The 300 mm pilot mill of source document 003 sec. 6.2 as an axial slice, see
# doc/mill.md: three speeds, about 15-25 min on 2 shared cores (MILL_SETTLE, MILL_AVE,
# MILL_SPEEDS, MILL_SMOOTH=1 for fig. 6.13's smooth mill: tools/mill/reproduce.sh).
reproduce-mill: deps
	@sh tools/deps.sh gnuplot-nox
	@$(MAKE) --no-print-directory all
	@sh tools/mill/reproduce.sh

# The mill's sensitivity to softening, slice length and end plates, time step, fill and
# tangential law (doc/mill.md, Sensitivity): 8 runs of 4 revolutions at 70 %, hours on
# 2 cores. Checkpoints with restart files: run it again after an interruption and it resumes.
mill-sensitivity: all
	@sh tools/mill/sensitivity.sh

# The avalanche of source document 002 run to its end by gravel and by LAMMPS on 1 and 2
# processes, compared statistically (inputs/published/avalanche/README.md); the full deck
# takes many hours here (AVAL_VARS="-var ly 0.36" for a narrow slab). Resumes after an interruption.
compare-avalanche: deps
	@sh tools/deps.sh gnuplot-nox
	@$(MAKE) --no-print-directory all
	@sh tools/avalanche/compare.sh

clean:
	rm -rf build bin
