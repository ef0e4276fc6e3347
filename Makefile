# cyclic-triax: the two commands a user needs are `make all` and `make test`.
BUILD    ?= build
JOBS     ?= $(shell nproc 2>/dev/null || echo 2)
PACKAGES := g++ cmake make libeigen3-dev libhdf5-dev libyaml-cpp-dev catch2 gnuplot-nox hdf5-tools
SUDO     := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

.PHONY: all deps build test bench quick samples clean

all: deps build test samples

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

# The three preparation scenes of SPEC section 2, full size (8,000 spheres).
samples: build
	mkdir -p results/samples
	for d in loose medium dense; do \
	  $(BUILD)/bin/dem run scenes/prepare_$$d.yaml --out results/samples/$$d.h5 || exit 1; \
	done

clean:
	rm -rf $(BUILD)
