# bentray: one C binary, built with pkg-config, warnings as errors.
#   make deps   install the Debian packages the project needs (idempotent)
#   make demo   build and render the default scene headless to a PNG
#   make install  the program, its man page (docs/bentray.1) and bash completion under PREFIX
#   make test   build and run every test
#   make golden re-render the committed golden images (on purpose only; look at them)
#   make bench  measure speed and speed against error: docs/BENCH.md, docs/bench/ (CSV, PNG plots)
#   make vm-test  the kiosk on a virtual exhibit (QEMU, KMS, systemd, GPIO): build/vm/vm-test.log
#   make shader-stats  every shader compiled by the exhibit GPUs' real compilers: docs/bench/shader_stats.md

CC      ?= cc
BUILD   ?= build
CFLAGS  ?= -O2 -g
CFLAGS  += -std=c11 -D_POSIX_C_SOURCE=200809L -Wall -Wextra -Werror -Wshadow -Wstrict-prototypes -Isrc -I$(BUILD)/gen
# make test-sanitize builds everything again under build/asan with these
CFLAGS  += $(SANITIZE)
BIN     ?= bentray
PKGS    := egl inih libpng freetype2 hidapi-libusb libgpiod x11 gbm libdrm libsystemd
HAVE_OSMESA := $(shell pkg-config --exists osmesa 2>/dev/null && echo 1)
ifeq ($(HAVE_OSMESA),1)
PKGS    += osmesa
CFLAGS  += -DHAVE_OSMESA=1
endif
PKG_CFLAGS := $(shell pkg-config --cflags $(PKGS) 2>/dev/null)
PKG_LIBS   := $(shell pkg-config --libs $(PKGS) 2>/dev/null)
LDLIBS  += $(PKG_LIBS) -lm -lpthread
# Tests only: cmocka, and GSL's special functions as an independent source of closed forms.
TEST_LIBS := -lcmocka $(shell pkg-config --libs gsl 2>/dev/null)

# Debian packages: build tools, GL stacks (EGL surfaceless + OSMesa on Mesa), libraries, test tools
# (glslang's validator checks that the shaders bentray prints keep to GLSL ES 1.00).
DEB_PACKAGES := make gcc pkg-config libegl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri \
                libosmesa6-dev libinih-dev libpng-dev libcmocka-dev libgsl-dev \
                libhidapi-dev libgpiod-dev libsystemd-dev libfreetype-dev fonts-dejavu-core \
                libgbm-dev libdrm-dev libx11-dev xvfb xauth valgrind groff-base \
                glslang-tools xplanet marble-qt-data

LIB_SRCS  := $(shell find src -name '*.c' ! -path 'src/tools/*' ! -name main.c | sort)
LIB_OBJS  := $(LIB_SRCS:%.c=$(BUILD)/%.o) $(BUILD)/gen/shaders_embedded.o
SHADERS   := $(sort $(wildcard shaders_es/*.glsl))
TEST_SRCS := $(sort $(wildcard tests/unit/test_*.c))
TEST_BINS := $(TEST_SRCS:tests/unit/%.c=$(BUILD)/tests/%)

.PHONY: all deps deps-bench deps-gallery deps-vm vm-test shader-stats gallery install demo check-layers test test-unit test-render test-sanitize test-valgrind golden assets accuracy bench clean
all: $(BIN)

# The version: the commit this tree was built from (git describe), or "unknown" outside a checkout;
# main.o is rebuilt when it changes.
VERSION := $(shell git describe --always --dirty 2>/dev/null || echo unknown)
$(BUILD)/gen/version: FORCE
	@mkdir -p $(dir $@)
	@echo '$(VERSION)' | cmp -s - $@ || echo '$(VERSION)' > $@
$(BUILD)/src/main.o: $(BUILD)/gen/version
$(BUILD)/src/main.o: CFLAGS += -DBENTRAY_VERSION='"$(VERSION)"'
.PHONY: FORCE
FORCE:

$(BIN): $(BUILD)/src/main.o $(BUILD)/libbentray.a
	$(CC) $(CFLAGS) -o $@ $^ $(LDLIBS)

$(BUILD)/libbentray.a: $(LIB_OBJS)
	@rm -f $@
	ar rcs $@ $^

$(BUILD)/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(PKG_CFLAGS) -MMD -MP -c -o $@ $<

# The machine's limit for `bentray bench`: the C kernel is vectorised by the compiler for this CPU
# (gcc 12 leaves it scalar at -O2; sqrtf's errno path blocks vectorisation). No -ffast-math: the
# arithmetic stays the shader's.
$(BUILD)/src/bench/cpu_limit.o: CFLAGS += -O3 -march=native -fno-math-errno

# Shaders are compiled into the binary: one table of (file name, text).
$(BUILD)/tools/embed: src/tools/embed.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -o $@ $<
$(BUILD)/gen/shaders_embedded.c: $(BUILD)/tools/embed $(SHADERS)
	@mkdir -p $(dir $@)
	$(BUILD)/tools/embed $@ $(SHADERS)
$(BUILD)/gen/shaders_embedded.o: $(BUILD)/gen/shaders_embedded.c
	$(CC) $(CFLAGS) -c -o $@ $<

# Generated assets (checkerboards, star field, test sky) come from the project's own tool.
$(BUILD)/tools/gen_assets: src/tools/gen_assets.c src/io/png_io.c src/io/output_file.c src/io/text_file.c src/io/error.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(PKG_CFLAGS) -o $@ $^ $(PKG_LIBS) -lm
assets: $(BUILD)/tools/gen_assets
	$(BUILD)/tools/gen_assets assets

# Every scene on the GPU in several configurations against the CPU reference: docs/ACCURACY.md.
$(BUILD)/tools/accuracy_report: src/tools/accuracy_report.c $(BUILD)/libbentray.a
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(PKG_CFLAGS) -o $@ $^ $(LDLIBS)
accuracy: deps
	@$(MAKE) --no-print-directory $(BUILD)/tools/accuracy_report
	$(BUILD)/tools/accuracy_report assets/scenes docs/ACCURACY.md

# gnuplot draws the bench plots; only `make bench` needs it.
BENCH_PACKAGES := gnuplot-nox

deps-bench:
	@$(MAKE) --no-print-directory deps DEB_PACKAGES="$(BENCH_PACKAGES)"

# The whole benchmark (about half an hour here), then the plots from its gnuplot scripts.
bench: deps deps-bench
	@$(MAKE) --no-print-directory bentray
	./bentray bench --out docs --force
	cd docs/bench && for g in *.gp; do gnuplot "$$g"; done

deps:
	@missing=$$(for p in $(DEB_PACKAGES); do dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q '^install ok installed' || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  echo "installing:" $$missing; \
	  SUDO=; [ "$$(id -u)" = 0 ] || SUDO=sudo; \
	  $$SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends $$missing || \
	  { $$SUDO apt-get update -qq && $$SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends $$missing; }; \
	fi

# make install [PREFIX=/usr/local] [DESTDIR=]: the program, its man page and its bash completion.
# (The kiosk's service, scenes and rules: kiosk/install.sh, docs/KIOSK.md.)
PREFIX ?= /usr/local
install: $(BIN)
	install -d $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/share/man/man1 \
	    $(DESTDIR)$(PREFIX)/share/bash-completion/completions
	install -m 0755 $(BIN) $(DESTDIR)$(PREFIX)/bin/bentray
	install -m 0644 docs/bentray.1 $(DESTDIR)$(PREFIX)/share/man/man1/bentray.1
	install -m 0644 shell/bentray.bash $(DESTDIR)$(PREFIX)/share/bash-completion/completions/bentray

GALLERY_PACKAGES := ffmpeg

deps-gallery:
	@$(MAKE) --no-print-directory deps DEB_PACKAGES="$(GALLERY_PACKAGES)"

# docs/GALLERY.md and docs/gallery/: every scene's image and one animation, by the project's own
# commands (docs/gallery/make.sh).
gallery: deps deps-gallery
	@$(MAKE) --no-print-directory bentray
	docs/gallery/make.sh

VM_PACKAGES := qemu-system-x86 qemu-utils debootstrap e2fsprogs python3

deps-vm:
	@$(MAKE) --no-print-directory deps DEB_PACKAGES="$(VM_PACKAGES)"

# The kiosk deployed on a virtual exhibit (docs/KIOSK.md, "The virtual exhibit"): Debian 12 in
# QEMU on KMS, installed by kiosk/install.sh, driven through its keyboard, GPIO lines and systemd.
# Not part of make test (about 10 minutes without KVM, and it needs root); run it before every
# change to the kiosk is committed. Log: build/vm/vm-test.log.
vm-test: deps deps-vm
	@$(MAKE) --no-print-directory bentray
	tests/vm/run.sh

# Every shader program of the shipped scenes and the kiosk, compiled by the real compilers of the
# exhibit's GPUs (VC4, V3D, Mali-400, Mali-T720, Mali-G52, Adreno 306 and 530: Mesa's drivers over
# their noop drm-shim, built under build/mesa-shim from Debian's Mesa source the first time, about
# twenty minutes). Writes docs/bench/shader_stats.md, which docs/BENCH.md includes. Not part of make
# test; its result is committed. SHADER_STATS_FLAGS=--kiosk compiles only the kiosk's programs.
shader-stats: deps
	@$(MAKE) --no-print-directory bentray $(BUILD)/tests/gpus/compile_stats
	tests/gpus/shader_stats.sh $(SHADER_STATS_FLAGS) docs/bench/shader_stats.md

# compile_stats is built by make test too (tests/render/shader_dump.sh uses it on llvmpipe)
$(BUILD)/tests/gpus/compile_stats: tests/gpus/compile_stats.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -o $@ $< $(shell pkg-config --libs egl glesv2)

demo: deps
	@$(MAKE) --no-print-directory bentray
	@mkdir -p out
	./bentray render --scene assets/scenes/demo.scene --out out/demo.png --force
	@echo "$(CURDIR)/out/demo.png"

$(BUILD)/tests/%: tests/unit/%.c $(BUILD)/libbentray.a
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(PKG_CFLAGS) -Itests -MMD -MP -MF $@.d -o $@ $< $(BUILD)/libbentray.a $(LDLIBS) $(TEST_LIBS)

test: deps
	@$(MAKE) --no-print-directory check-layers test-unit test-render test-valgrind test-sanitize

# No module includes one above it (docs/ARCHITECTURE.md).
check-layers:
	@sh tests/check_layers.sh

test-unit: $(TEST_BINS)
	@set -e; for t in $(TEST_BINS); do echo "== $$t"; $$t; done

# the report tool is built here too, so that it cannot rot between runs of `make accuracy`
test-render: $(BIN) $(BUILD)/tools/accuracy_report $(BUILD)/tests/gpus/compile_stats
	@BT=./$(BIN) tests/render/run_all.sh

# One headless render on each back-end (EGL, OSMesa) under Valgrind's memcheck: a definite leak or an
# invalid access in bentray fails it; Mesa's own leaks are suppressed in tests/render/valgrind.supp
# (driver objects only). The optimised binary: a sanitizer build cannot run under Valgrind.
test-valgrind: $(BIN)
	@BT=./$(BIN) tests/render/valgrind_render.sh

# The unit and command-line tests again, built with AddressSanitizer and UndefinedBehaviorSanitizer:
# an invalid access or an undefined operation fails the test that caused it, and so does a leak in
# the tests that open no GL context. Those that do (GL_TESTS, found by what they include) and the
# command-line tests run without leak detection: Mesa unloads its driver before LeakSanitizer looks,
# so the driver's allocations can no longer be told from ours.
SANITIZE_FLAGS := -O1 -g -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer
ASAN_BINS := $(TEST_BINS:$(BUILD)/%=build/asan/%)
GL_TESTS  := $(basename $(notdir $(shell grep -l 'hard_cases.h\|gl_context_create\|render_frame\|kiosk_run' $(TEST_SRCS))))
test-sanitize:
	@$(MAKE) --no-print-directory BUILD=build/asan BIN=build/asan/bentray SANITIZE="$(SANITIZE_FLAGS)" \
	    build/asan/bentray build/asan/tests/gpus/compile_stats $(ASAN_BINS)
	@set -e; export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1; \
	  for t in $(ASAN_BINS); do \
	    case " $(GL_TESTS) " in *" $$(basename $$t) "*) leaks=0;; *) leaks=1;; esac; \
	    echo "== $$t (sanitized, leak detection $$leaks)"; \
	    ASAN_OPTIONS=detect_leaks=$$leaks $$t > build/asan/last.log 2>&1 || { cat build/asan/last.log; exit 1; }; \
	  done; \
	  ASAN_OPTIONS=detect_leaks=0 BT=build/asan/bentray COMPILE_STATS=build/asan/tests/gpus/compile_stats \
	    tests/render/run_all.sh

# Fuzzing (libFuzzer; clang only, so not part of `make test`): the parsers of what exhibition staff
# edit (scene files, the kiosk configuration), the dump reader and the input decoders, each harness
# (tests/fuzz/fuzz_TARGET.c) with AddressSanitizer and UndefinedBehaviorSanitizer. The seeds
# (tests/fuzz/seeds/TARGET/, never written to) are copied into a working corpus,
# build/fuzz/corpus/TARGET, which grows from run to run.
#   make fuzz [FUZZ_SECONDS=60]  each harness for FUZZ_SECONDS, then docs/RELIABILITY.md and the
#                                running totals in docs/fuzz_totals.csv (tests/fuzz/report.sh)
#   make fuzz-smoke              each harness for 5 seconds, nothing written outside build/ (for CI)
# A crash, a leak, a timeout or an out-of-memory fails the target and prints its reproducer,
# build/fuzz/crashes/TARGET/...: `build/fuzz/fuzz_TARGET FILE` runs that input again.
FUZZ_PACKAGES := clang libclang-rt-14-dev
FUZZ_CC       ?= clang
FUZZ_SECONDS  ?= 60
# Seconds one input may run before libFuzzer calls it a hang. Every input of the corpus runs in well
# under a second alone; a run niced beside builds and tests on two cores can stall an input for
# longer than that on the wall clock, so such a run passes a larger value (FUZZ_TIMEOUT=60).
FUZZ_TIMEOUT  ?= 10
FUZZ_TARGETS  := conf scene kiosk_config dump hid gpio script
FUZZ_DIR      := $(BUILD)/fuzz
# -fno-sanitize-recover: undefined behaviour stops the run, so that libFuzzer keeps the input
FUZZ_CFLAGS   := -std=c11 -D_POSIX_C_SOURCE=200809L -Wall -Wextra -Werror -Wshadow -Wstrict-prototypes \
                 -Isrc -g -O1 -fsanitize=address,undefined -fno-sanitize-recover=undefined \
                 -fno-omit-frame-pointer $(shell pkg-config --cflags inih libpng egl hidapi-libusb libgpiod 2>/dev/null)
FUZZ_LIBS     := $(shell pkg-config --libs inih libpng hidapi-libusb libgpiod 2>/dev/null) -lm
# The harnesses link one library of the modules below the GL code (docs/ARCHITECTURE.md: io, conf,
# physics, scene, results, input, kiosk_config), built with the sanitizers; each takes from it
# only the objects it calls, so no harness keeps a list of source files.
FUZZ_LIB_MODULES := io conf physics scene results input kiosk_config
FUZZ_LIB_SRCS := $(foreach m,$(FUZZ_LIB_MODULES),$(filter src/$(m)/%,$(LIB_SRCS)))
FUZZ_LIB      := $(FUZZ_DIR)/libbentray_fuzz.a
FUZZ_BINS     := $(FUZZ_TARGETS:%=$(FUZZ_DIR)/fuzz_%)
# Where the harnesses write their input as a file: from tree/scenes, a scene's ../textures and
# ../sky, and from tree/kiosk, the configuration's ../assets, are the project's, as from
# assets/scenes and kiosk/.
FUZZ_TREE     := $(FUZZ_DIR)/tree

.PHONY: deps-fuzz fuzz fuzz-smoke fuzz-build fuzz-run

deps-fuzz:
	@$(MAKE) --no-print-directory deps DEB_PACKAGES="$(FUZZ_PACKAGES)"

$(FUZZ_DIR)/%.o: %.c
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_CFLAGS) -fsanitize=fuzzer-no-link -MMD -MP -c -o $@ $<

$(FUZZ_LIB): $(FUZZ_LIB_SRCS:%.c=$(FUZZ_DIR)/%.o)
	@rm -f $@
	$(AR) rcs $@ $^
	@# the source the harnesses were built from, for the report (tests/fuzz/report.sh)
	@{ git rev-parse --short HEAD 2>/dev/null || echo unknown; } | tr -d '\n' > $(FUZZ_DIR)/source
	@if [ -n "$$(git status --porcelain -- src 2>/dev/null)" ]; then \
	  printf ' (with uncommitted changes in src/)' >> $(FUZZ_DIR)/source; fi

$(FUZZ_DIR)/fuzz_%: tests/fuzz/fuzz_%.c $(FUZZ_LIB)
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_CFLAGS) -fsanitize=fuzzer -MMD -MP -MF $@.d -o $@ $< $(FUZZ_LIB) $(FUZZ_LIBS)

fuzz-build: $(FUZZ_BINS)

fuzz: deps deps-fuzz
	@$(MAKE) --no-print-directory fuzz-run FUZZ_REPORT=1

fuzz-smoke: deps deps-fuzz
	@$(MAKE) --no-print-directory fuzz-run FUZZ_SECONDS=5 FUZZ_REPORT=0

fuzz-run: $(FUZZ_BINS)
	@rm -rf $(FUZZ_DIR)/logs $(FUZZ_TREE)
	@mkdir -p $(FUZZ_DIR)/logs $(FUZZ_TREE)/scenes $(FUZZ_TREE)/kiosk
	@ln -s $(CURDIR)/assets $(FUZZ_TREE)/assets
	@ln -s $(CURDIR)/assets/textures $(FUZZ_TREE)/textures
	@ln -s $(CURDIR)/assets/sky $(FUZZ_TREE)/sky
	@status=0; for t in $(FUZZ_TARGETS); do \
	  corpus=$(FUZZ_DIR)/corpus/$$t; crashes=$(FUZZ_DIR)/crashes/$$t; log=$(FUZZ_DIR)/logs/$$t.log; \
	  case $$t in scene) tmp=$(FUZZ_TREE)/scenes;; kiosk_config) tmp=$(FUZZ_TREE)/kiosk;; *) tmp=$(FUZZ_TREE);; esac; \
	  mkdir -p $$corpus $$crashes; \
	  for s in tests/fuzz/seeds/$$t/*; do [ -f "$$s" ] && cp -n "$$s" $$corpus/; done; \
	  echo "== fuzz_$$t: $(FUZZ_SECONDS) s, corpus $$corpus ($$(ls $$corpus | wc -l) inputs)"; \
	  BT_FUZZ_TMPDIR=$$tmp UBSAN_OPTIONS=print_stacktrace=1 \
	    $(FUZZ_DIR)/fuzz_$$t -max_total_time=$(FUZZ_SECONDS) -timeout=$(FUZZ_TIMEOUT) -print_final_stats=1 \
	    -artifact_prefix=$$crashes/ $$corpus > $$log 2>&1; \
	  rc=$$?; echo $$rc > $(FUZZ_DIR)/logs/$$t.rc; \
	  rm -f $$tmp/bt_fuzz_*; \
	  if [ $$rc -eq 0 ]; then \
	    sed -n 's/^stat::number_of_executed_units: */   executions: /p' $$log; \
	  else \
	    status=1; grep -m1 -A12 'ERROR\|runtime error\|deadly signal' $$log; \
	    repro=$$(sed -n 's/^.*Test unit written to //p' $$log | tail -n 1); \
	    echo "fuzz_$$t FAILED (exit $$rc), reproducer: $${repro:-none written, see $$log}"; \
	    [ -z "$$repro" ] || echo "  run it again: $(FUZZ_DIR)/fuzz_$$t $$repro"; \
	  fi; \
	done; \
	if [ "$(FUZZ_REPORT)" = 1 ]; then tests/fuzz/report.sh $(FUZZ_DIR) $(FUZZ_SECONDS) $(FUZZ_TARGETS) || status=1; fi; \
	exit $$status

golden: bentray
	tests/render/make_golden.sh

clean:
	rm -rf $(BUILD) bentray

# the compilers' dependency files (not build/vm/, where a guest's /etc holds directories named *.d)
-include $(shell find $(BUILD) -path $(BUILD)/vm -prune -o -type f -name '*.d' -print 2>/dev/null)
