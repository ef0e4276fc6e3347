# cyclic-triax: the two commands a user needs are `make all` and `make test`.
BUILD    ?= build
JOBS     ?= $(shell nproc 2>/dev/null || echo 2)
PACKAGES := g++ cmake make libeigen3-dev libhdf5-dev libyaml-cpp-dev catch2 gnuplot-nox hdf5-tools
SUDO     := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

.PHONY: all deps build test bench quick study samples samples-study cyclic-tests clean

# Until the study pipeline (issue 5) exists: build, test, prepare the three samples, run the five
# cyclic tests on each, and write the sample table.
all: deps build test samples cyclic-tests

# Install only the Debian packages that are missing (non-interactive).
deps:
	@missing=""; for p in $(PACKAGES); do dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  echo "installing:$$missing"; \
	  $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get update -qq && \
	  $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $$missing; \
	else echo "deps: all present"; fi

build: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null
	cmake --build $(BUILD) -j $(JOBS)

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

bench: build
	$(BUILD)/bin/dem-bench $(BUILD)/bench

# The study through the pipeline (issue 5): every density x test, reusing finished results.
study: build
	$(BUILD)/bin/pipeline pipeline/studies/paper.yaml --profile paper -j $(JOBS)

# The same with the quick profile (1,000 spheres, at most 2 cycles per repeat block).
quick: build
	$(BUILD)/bin/pipeline pipeline/studies/paper.yaml --profile quick -j $(JOBS)

# The three preparation scenes of SPEC section 2, full size (8,000 spheres), seed 1; then the table.
samples: build
	mkdir -p results/samples
	for d in dense medium loose; do \
	  [ -f results/samples/$${d}_n20_s1_viscous.h5 ] || \
	  $(BUILD)/bin/dem run scenes/prepare_$$d.yaml --out results/samples/$${d}_n20_s1_viscous.h5 \
	    --set name=prepare_$${d}_n20_s1_viscous || exit 1; \
	done
	reports/samples/make_table.sh $(BUILD)/bin/dem results/samples > reports/samples/table.md

# Issue 3's whole sample study: 3 seeds x 3 sizes x 3 densities, and local damping (hours).
samples-study: build
	reports/samples/run_samples.sh $(BUILD)/bin/dem results/samples
	reports/samples/make_table.sh $(BUILD)/bin/dem results/samples > reports/samples/table.md

# The five cyclic tests (scenes/tests) on each full-size sample.
cyclic-tests: samples
	reports/samples/run_tests.sh $(BUILD)/bin/dem "dense medium loose"

clean:
	rm -rf $(BUILD)
