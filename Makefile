# Convenience wrapper: installs dependencies, configures through CMake presets, builds, runs.

# `ci` (warnings as errors) when the CI environment variable is "true", `default` otherwise.
PRESET ?= $(if $(filter true,$(CI)),ci,default)
BUILD_DIR := build
FUZZ_SECONDS ?= 600
ROOT := 'RoverSystem()'
FORMAT_DIRS := bipc engines monitors smc tests bench
PREFIX ?= /usr/local

.PHONY: all deps build tools install demo test test-asan test-slow fuzz fuzz-build fuzz-smoke bench bench-engines bench-generated bench-monitor bench-check bench-peers bench-mpi format clean

all: build

deps:
	scripts/install-deps.sh

build: deps
	cmake --preset $(PRESET)
	cmake --build --preset $(PRESET)

# The tools alone (bipc, smcbip, taste2bip) and the libraries they link: what `make demo` runs,
# without the tests, benchmarks and runtime targets that `build` makes.
TOOL_TARGETS := bipc_tool smcbip taste2bip_tool

tools: deps
	cmake --preset $(PRESET)
	cmake --build --preset $(PRESET) --target $(TOOL_TARGETS)

# The libraries, headers, tools and CMake package (find_package(smcbip)) under $(PREFIX).
install: build
	cmake --install $(BUILD_DIR) --prefix $(PREFIX)

demo: tools
	$(BUILD_DIR)/bin/bipc check models/rover_watchdog.bip --root $(ROOT)
	$(BUILD_DIR)/bin/bipc ir models/rover_watchdog.bip --root $(ROOT)
	$(BUILD_DIR)/bin/bipc dot models/rover_watchdog.bip --root $(ROOT) -o $(BUILD_DIR)/rover_watchdog.svg
	@echo "The architecture picture is in $(BUILD_DIR)/rover_watchdog.svg"
	$(BUILD_DIR)/bin/smcbip simulate models/families/rendezvous_10.bip --root 'Top()' --seed 1 --limit 5
	$(BUILD_DIR)/bin/smcbip simulate models/channel.bip --root 'System()' --seed 1 --limit 8
	$(BUILD_DIR)/bin/smcbip simulate models/channel.bip --root 'System()' --seed 1 --limit 2 --trace jsonl
	$(BUILD_DIR)/bin/smcbip check models/channel.bip models/channel.mtl --root 'System()' --delta 0.02
	$(BUILD_DIR)/bin/smcbip explore models/channel.bip models/channel_sweep.mtl --root 'System()' --delta 0.02 --plot $(BUILD_DIR)/channel_sweep.svg --csv $(BUILD_DIR)/channel_sweep.csv || [ $$? -eq 1 ]
	@echo "The sweep's plot is in $(BUILD_DIR)/channel_sweep.svg"
	$(BUILD_DIR)/bin/taste2bip models/taste/rover/interfaceview.xml -o $(BUILD_DIR)/rover_taste
	$(BUILD_DIR)/bin/smcbip check $(BUILD_DIR)/rover_taste/taste.bip models/taste/rover/properties.mtl --root 'Syst()' --seed 1

test: build
	ctest --test-dir $(BUILD_DIR) --output-on-failure -LE slow -j2
	$(MAKE) fuzz-smoke

# The quick tests built with AddressSanitizer and UndefinedBehaviorSanitizer (a second full build,
# in build-asan). CI runs the tools' whole-run tests under the sanitizers instead (.ci/run).
test-asan: deps
	cmake --preset asan
	cmake --build --preset asan
	ctest --test-dir build-asan --output-on-failure -L quick -j2 -E '$(ASAN_SKIPPED)'

# What test-asan leaves out: under the sanitizers these repeat the same arithmetic at ten to forty
# times the cost (some 15 minutes): four statistical tests of smc, the watchdog's exhaustive
# trace comparisons and property answers (whose code the shorter Watchdog tests run), and the
# FDIR mission's two statistical golden runs.
ASAN_SKIPPED := BernoulliModel.EstimatesCoverTheirProbability|Accuracy.UniformWindowsRacing|Check.EstimatesTheTandemQueueAsPrismDoes|Accuracy.SumsOfDelays|WatchdogCompare\.|WatchdogSameAnswers\.|WatchdogProperties\.|fdir\.golden\.fdir_mission_

test-slow: build
	ctest --test-dir $(BUILD_DIR) --output-on-failure -L slow -j2

# The fuzzers, each with its seeds and dictionary. Seeds are files of the tree and what
# tests/fuzz_seeds.sh makes of the bundled models (IR encodings, traces of short runs) in
# build-fuzz/seeds; new inputs go to build-fuzz/corpus/<target>, never into the tree.
FUZZ_TARGETS := bipc property trace ir cdf asn1 aadl xml sdl sdlatom pus
FUZZ_SEEDS_bipc := tests/bipc/golden/valid models
FUZZ_SEEDS_property := build-fuzz/seeds/properties
FUZZ_SEEDS_trace := tests/smc/golden/traces build-fuzz/seeds/traces
FUZZ_SEEDS_ir := build-fuzz/seeds/ir
FUZZ_SEEDS_cdf := tests/engines/fuzz/seeds
FUZZ_SEEDS_asn1 := tests/taste2bip/fuzz/seeds/asn1
FUZZ_SEEDS_aadl := tests/taste2bip/fuzz/seeds/aadl
FUZZ_SEEDS_xml := tests/taste2bip/fuzz/seeds/xml
FUZZ_SEEDS_sdl := tests/taste2bip/fuzz/seeds/sdl
FUZZ_SEEDS_sdlatom := tests/taste2bip/fuzz/seeds/sdlatom
FUZZ_SEEDS_pus := tests/pus/fuzz/seeds/pus
FUZZ_DICT_bipc := tests/bipc/fuzz/bip.dict
FUZZ_DICT_property := tests/monitors/fuzz/property.dict
FUZZ_DICT_trace := tests/monitors/fuzz/trace.dict
FUZZ_DICT_ir := tests/bipc/fuzz/ir.dict
FUZZ_DICT_cdf := tests/engines/fuzz/cdf.dict
FUZZ_DICT_asn1 := tests/taste2bip/fuzz/asn1.dict
FUZZ_DICT_aadl := tests/taste2bip/fuzz/aadl.dict
FUZZ_DICT_xml := tests/taste2bip/fuzz/xml.dict
FUZZ_DICT_sdl := tests/taste2bip/fuzz/sdl.dict
FUZZ_DICT_sdlatom := tests/taste2bip/fuzz/sdl.dict
FUZZ_DICT_pus := tests/pus/fuzz/pus.dict
# The smoke run of `make test`: three minutes in all, 40 s for the front end, 20 s for each
# other reader of models, properties and traces, 10 s for each reader of TASTE designs, for the
# SDL translation and for the PUS packet decoder.
FUZZ_SMOKE_SECONDS_bipc := 40
FUZZ_SMOKE_SECONDS_property := 20
FUZZ_SMOKE_SECONDS_trace := 20
FUZZ_SMOKE_SECONDS_ir := 20
FUZZ_SMOKE_SECONDS_cdf := 20
FUZZ_SMOKE_SECONDS_asn1 := 10
FUZZ_SMOKE_SECONDS_aadl := 10
FUZZ_SMOKE_SECONDS_xml := 10
FUZZ_SMOKE_SECONDS_sdl := 10
FUZZ_SMOKE_SECONDS_sdlatom := 10
FUZZ_SMOKE_SECONDS_pus := 10

# $(call fuzz_run,TARGET,SECONDS): one fuzzer for SECONDS from its corpus and seeds.
define fuzz_run
	mkdir -p build-fuzz/corpus/$(1)
	build-fuzz/bin/$(1)_fuzz -dict=$(FUZZ_DICT_$(1)) -max_total_time=$(2) -timeout=10 \
	  build-fuzz/corpus/$(1) $(FUZZ_SEEDS_$(1))

endef

# The seeds are made by the tools of the plain build (which `make test` has built already).
fuzz-build: deps
	cmake --preset $(PRESET)
	cmake --build --preset $(PRESET) --target bipc_ir_seeds smcbip
	tests/fuzz_seeds.sh $(BUILD_DIR) build-fuzz/seeds
	cmake --preset fuzz
	cmake --build --preset fuzz --target $(FUZZ_TARGETS:%=%_fuzz)

# The short run that `make test` includes; `make fuzz` is the long one (FUZZ_SECONDS each).
fuzz-smoke: fuzz-build
	$(foreach t,$(FUZZ_TARGETS),$(call fuzz_run,$(t),$(FUZZ_SMOKE_SECONDS_$(t))))

fuzz: fuzz-build
	$(foreach t,$(FUZZ_TARGETS),$(call fuzz_run,$(t),$(FUZZ_SECONDS)))

bench: build
	bench/frontend_scaling.sh $(BUILD_DIR)

# Steps per second of the three schedulers (reports, never fails on timings).
bench-engines: build
	bench/engines_steps.sh $(BUILD_DIR)

# Steps per second of generated against interpreted models (reports, never fails on timings).
bench-generated: build
	bench/generated_steps.sh $(BUILD_DIR)

# Runs per second of smcbip check on one thread and on all cores (reports, never fails).
bench-check: build
	bench/check_runs.sh $(BUILD_DIR)

# smcbip check beside Ymer and PRISM (YMER=... PRISM=... point to them; reports, never fails).
bench-peers: build
	bench/peers.sh $(BUILD_DIR)

# smcbip check on 1 process and on MPI jobs of 2 to 4 ranks; the consumer's own cost per run.
bench-mpi: build
	bench/mpi_ranks.sh $(BUILD_DIR)

# The online monitor's events per second and memory on million-event traces.
bench-monitor: build
	$(BUILD_DIR)/bin/monitor_events

format:
	find $(FORMAT_DIRS) \( -name '*.cpp' -o -name '*.h' \) -print0 2>/dev/null \
	  | xargs -0 -r clang-format-14 -i

clean:
	rm -rf build build-asan build-fuzz
