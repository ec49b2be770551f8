# bentray: one C binary, built with pkg-config, warnings as errors.
#   make deps   install the Debian packages the project needs (idempotent)
#   make demo   build and render the default scene headless to a PNG
#   make test   build and run every test
#   make golden re-render the committed golden images (on purpose only; look at them)
#   make bench  measure speed and speed against error: docs/BENCH.md, docs/bench/ (CSV, PNG plots)

CC      ?= cc
BUILD   ?= build
CFLAGS  ?= -O2 -g
CFLAGS  += -std=c11 -D_POSIX_C_SOURCE=200809L -Wall -Wextra -Werror -Wshadow -Wstrict-prototypes -Isrc -I$(BUILD)/gen
# make test-sanitize builds everything again under build/asan with these
CFLAGS  += $(SANITIZE)
BIN     ?= bentray
PKGS    := egl inih libpng
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

# Debian packages: build tools, GL stacks (EGL surfaceless + OSMesa on Mesa), libraries, test tools.
DEB_PACKAGES := make gcc pkg-config libegl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri \
                libosmesa6-dev libinih-dev libpng-dev libcmocka-dev libgsl-dev

LIB_SRCS  := $(shell find src -name '*.c' ! -path 'src/tools/*' ! -name main.c | sort)
LIB_OBJS  := $(LIB_SRCS:%.c=$(BUILD)/%.o) $(BUILD)/gen/shaders_embedded.o
SHADERS   := $(sort $(wildcard shaders_es/*.glsl))
TEST_SRCS := $(sort $(wildcard tests/unit/test_*.c))
TEST_BINS := $(TEST_SRCS:tests/unit/%.c=$(BUILD)/tests/%)

.PHONY: all deps deps-bench demo test test-unit test-render test-sanitize golden assets accuracy bench clean
all: $(BIN)

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
$(BUILD)/tools/gen_assets: src/tools/gen_assets.c src/io/png_io.c
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

# The whole benchmark (about 25 minutes here), then the plots from its gnuplot scripts.
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

demo: deps
	@$(MAKE) --no-print-directory bentray
	@mkdir -p out
	./bentray render --scene assets/scenes/demo.scene --out out/demo.png --force
	@echo "$(CURDIR)/out/demo.png"

$(BUILD)/tests/%: tests/unit/%.c $(BUILD)/libbentray.a
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(PKG_CFLAGS) -Itests -MMD -MP -MF $@.d -o $@ $< $(BUILD)/libbentray.a $(LDLIBS) $(TEST_LIBS)

test: deps
	@$(MAKE) --no-print-directory test-unit test-render test-sanitize

test-unit: $(TEST_BINS)
	@set -e; for t in $(TEST_BINS); do echo "== $$t"; $$t; done

# the report tool is built here too, so that it cannot rot between runs of `make accuracy`
test-render: $(BIN) $(BUILD)/tools/accuracy_report
	@BT=./$(BIN) tests/render/run_all.sh

# The unit and command-line tests again, built with AddressSanitizer and UndefinedBehaviorSanitizer:
# an invalid access or an undefined operation fails the test that caused it, and so does a leak in
# the tests that open no GL context. Those that do (GL_TESTS, found by what they include) and the
# command-line tests run without leak detection: Mesa unloads its driver before LeakSanitizer looks,
# so the driver's allocations can no longer be told from ours.
SANITIZE_FLAGS := -O1 -g -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer
ASAN_BINS := $(TEST_BINS:$(BUILD)/%=build/asan/%)
GL_TESTS  := $(basename $(notdir $(shell grep -l 'hard_cases.h\|gl_context_create\|render_frame' $(TEST_SRCS))))
test-sanitize:
	@$(MAKE) --no-print-directory BUILD=build/asan BIN=build/asan/bentray SANITIZE="$(SANITIZE_FLAGS)" \
	    build/asan/bentray $(ASAN_BINS)
	@set -e; export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1; \
	  for t in $(ASAN_BINS); do \
	    case " $(GL_TESTS) " in *" $$(basename $$t) "*) leaks=0;; *) leaks=1;; esac; \
	    echo "== $$t (sanitized, leak detection $$leaks)"; \
	    ASAN_OPTIONS=detect_leaks=$$leaks $$t > build/asan/last.log 2>&1 || { cat build/asan/last.log; exit 1; }; \
	  done; \
	  ASAN_OPTIONS=detect_leaks=0 BT=build/asan/bentray tests/render/run_all.sh

golden: bentray
	tests/render/make_golden.sh

clean:
	rm -rf $(BUILD) bentray

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)
