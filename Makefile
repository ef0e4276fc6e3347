# cyclic-triax: the two commands a user needs are `make all` and `make test`.
BUILD    ?= build
JOBS     ?= $(shell nproc 2>/dev/null || echo 2)
# python3-h5py and python3-pandas: the README's Python lines and the clients' tests (tests/clients/),
# with Debian's interpreter, /usr/bin/python3 (a python3 earlier on PATH, e.g. pyenv's, lacks them);
# pybind11-dev, python3-dev, python3-numpy, python3-yaml: the Python module cyclic_triax (python/);
# python3-pytest, jupyter-nbconvert, python3-ipykernel: its tests and its notebook (examples/python/);
# cmark-gfm: reports/index.html from reports/index.md.
PACKAGES := g++ cmake make libeigen3-dev libhdf5-dev libyaml-cpp-dev catch2 gnuplot-nox hdf5-tools libboost-math-dev libboost-dev libcli11-dev nlohmann-json3-dev python3-h5py python3-pandas \
            pybind11-dev python3-dev python3-numpy python3-yaml python3-pytest jupyter-nbconvert python3-ipykernel cmark-gfm
SUDO     := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

RESULTS  ?= results/study/paper
SAMPLE   ?= seed1                       # the sample whose runs the single-run figures show
CONVERGENCE ?= results/convergence/paper
STABILITY   ?= results/stability/paper
DECISIONS   ?= results/decisions/paper
# The studies of readings at the paper's size (pipeline/studies/readings_<name>.yaml): their
# results are results/readings_<name>/paper, their tables reports/readings/<name>/ (a study not run
# yet has none, and the verdict table takes no causes from it).
READINGS    ?= loose medium_dense dashpot
CRITICAL_STATE ?= results/critical_state/paper
# The critical state at μ = 0.5 on 3 samples (pipeline/studies/critical_state_ensemble.yaml) and at
# two slower rates (critical_state_rates.yaml): the section passes each when it has run.
CRITICAL_STATE_ENSEMBLE ?= results/critical_state_ensemble/paper
CRITICAL_STATE_RATES    ?= results/critical_state_rates/paper
LIQUEFACTION   ?= results/liquefaction_loose/paper results/liquefaction_medium/paper
# The studies of the cell under full control that `make study`, and so `make all`, runs beside the
# others (empty: none): the constant-p shear to the critical state (17 runs; 30.6 min for 10 of them
# on this project's 2-core VM, docs/performance.md). The liquefaction ensembles (24 cyclic tests
# and 6 holds: 196 core-min measured on that VM, about 1 h 40 min on its 2 cores) would take
# make all past 2 h: `make liquefaction` runs them, and the report keeps their committed
# section until then; so do the critical state's ensemble and rates studies (`make critical-state`).
CELL_STUDIES   ?= pipeline/studies/critical_state.yaml
EXECUTOR    ?=                          # local or slurm (pipeline --executor); empty: the study files' executor key, else local

.PHONY: all deps build tools examples example-samples install test kill-test slurm-test sanitize clang-test fuzz bench quick study convergence report decisions decisions-report convergence-report stability-report critical-state-report liquefaction-report readings-report report-sections literature literature-report critical-state liquefaction samples samples-study cyclic-tests render calibration-demo calibration-example open-choices open-choices-check clean

# Everything: install, build the tools, run the full study (an ensemble of 5 samples per density,
# reusing finished runs), validate it, draw the figures and write reports/index.md (the tests are
# `make test`'s). Fails at the end if a must-pass validation row is inconsistent with the paper.
all: deps tools study report
	$(BUILD)/bin/validate --results $(RESULTS) --references reference_data/paper.yaml --out reports

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

# Only what the studies and the report use (not the tests or the benchmark: from nothing, 1 min 11 s
# instead of 2 min 38 s on this machine).
TOOLS := dem pipeline validate compare-runs ensemble-cycles figure-data report calibrate python_module
tools: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null
	cmake --build $(BUILD) -j $(JOBS) --target $(TOOLS)

# The examples (scenes/examples/*.yaml), each from a shipped 1,000-sphere sample
# (scenes/samples/) on one thread, into build/examples/ (each under a minute here; make test runs
# them shortened through ctest).
examples: tools
	@mkdir -p $(BUILD)/examples
	@for s in scenes/examples/*.yaml; do n=$$(basename $$s .yaml); \
	  echo "== $$s"; \
	  OMP_NUM_THREADS=1 $(BUILD)/bin/dem run $$s --out $(BUILD)/examples/$$n.h5 --threads 1 --no-resume --force --quiet || exit 1; \
	done

# The shipped samples: the three preparation scenes at 1,000 spheres (10 x 10 x 10 lattice, seed 1:
# the quick profile's first sample), about 7 s each. tests/examples/samples_test.sh checks that they
# are what this engine and these scenes make, bit for bit.
example-samples: tools
	@for d in loose medium dense; do \
	  OMP_NUM_THREADS=1 $(BUILD)/bin/dem run scenes/prepare_$$d.yaml --set 'particles.lattice.n=[10, 10, 10]' \
	    --out scenes/samples/$${d}_1k.h5 --threads 1 --no-resume --force --quiet && rm -f scenes/samples/$${d}_1k.xdmf || exit 1; \
	done

# Calibration (calibration/README.md, docs/calibration.md). The demonstration with a known answer:
# synthetic lab curves made by the engine on 5 specimens with parameters the calibration does not
# read (pipeline/studies/calibration_truth.yaml), then the stiffness and friction inferred from
# them from wide priors (pipeline/calibrations/synthetic_triaxial.yaml); the truth is set beside
# the posterior once it is final. Its report: reports/calibration/synthetic_triaxial/.
CAL_RESULTS := results/calibration/paper
CAL_POINTS := 0.0002,0.0005,0.001,0.002,0.005,0.01,0.02,0.04,0.07
CAL_REPORT := reports/calibration/synthetic_triaxial
calibration-demo: tools
	$(BUILD)/bin/pipeline pipeline/studies/calibration_truth.yaml -j $(JOBS)
	for y in q_over_p volumetric_strain; do \
	  $(BUILD)/bin/calibrate lab-curve --x strain_3 --y $$y --at $(CAL_POINTS) --out reference_data/calibration/synthetic_triaxial_$$y.csv \
	    $(foreach s,11 12 13 14 15,$(CAL_RESULTS)/seed$(s)/truth_dense_triaxial.h5) || exit 1; done
	$(BUILD)/bin/calibrate truth pipeline/calibrations/synthetic_triaxial.yaml $(CAL_RESULTS)/seed11/truth_dense_triaxial.h5 --out $(CAL_REPORT)/truth.json
	$(BUILD)/bin/calibrate pipeline/calibrations/synthetic_triaxial.yaml -j $(JOBS) --truth $(CAL_REPORT)/truth.json
	cd $(CAL_REPORT) && GNUPLOT_LIB=$(CURDIR)/reports/gnuplot gnuplot $(CURDIR)/reports/gnuplot/calibration.gp

# The paper's open choices calibrated jointly (pipeline/calibrations/paper_open_choices.yaml,
# docs/calibration.md): 16 sets an iteration at 512 spheres on 3 samples, 72-85 min an
# iteration on 2 cores as measured, over several sessions (finished runs are reused; the report is written
# after every iteration). Then open-choices-check: its best set at 8,000 spheres on 3 samples,
# judged like the paper study (54 runs; 99 min on 2 cores for the dashpot best set, measured;
# finished runs are reused across sessions). The study it runs, pipeline/studies/calibration_paper_best.yaml, is
# written from calibration_paper.yaml and the best set (calibrate variant).
OPEN := pipeline/calibrations/paper_open_choices.yaml
OPEN_REPORT := reports/calibration/paper_open_choices
open-choices: tools
	$(BUILD)/bin/calibrate $(OPEN) --profile small -j $(JOBS)
	cd $(OPEN_REPORT) && GNUPLOT_LIB=$(CURDIR)/reports/gnuplot gnuplot $(CURDIR)/reports/gnuplot/calibration.gp
open-choices-check: tools
	best=$$($(BUILD)/bin/calibrate variant $(OPEN)) || exit 1; \
	{ echo "# Written by make open-choices-check: calibration_paper.yaml with the calibration's best set as its one variant."; \
	  sed -e 's/^name: calibration_paper$$/name: calibration_paper_best/' \
	      -e 's|^output: ../../results/calibration$$|output: ../../results/calibration_paper_best|' pipeline/studies/calibration_paper.yaml; \
	  echo "variants:"; echo "  - $$best"; } > pipeline/studies/calibration_paper_best.yaml
	$(BUILD)/bin/pipeline pipeline/studies/calibration_paper_best.yaml --profile check -j $(JOBS)
	$(BUILD)/bin/validate --results results/calibration_paper_best/check --references reference_data/paper.yaml \
	  --out $(OPEN_REPORT)/best

# A calibration of your own, the example: examples/calibration/ (an illustrative lab curve), a few
# minutes on 2 cores; its report in results/calibration_example/report/.
calibration-example: tools
	$(BUILD)/bin/calibrate examples/calibration/calibration.yaml -j $(JOBS)
	cd results/calibration_example/report && GNUPLOT_LIB=$(CURDIR)/reports/gnuplot gnuplot $(CURDIR)/reports/gnuplot/calibration.gp

# The tools into PREFIX (bin/dem, bin/pipeline, ...; they run from any folder).
PREFIX ?= /usr/local
install: tools
	cmake --install $(BUILD) --prefix $(PREFIX)

# Unit tests (ctest: with them the report's web page in headless Chromium, which the test installs
# if missing: 48 s on this machine), then a smoke run of the whole pipeline (quick profile, into the build folder) with
# the validation rows that hold at that size, and the stability matrix on 27 spheres (216 for the
# jammed start): every case must run with its energy balance closed within 1 % or stop with a
# message (5.6 s on this machine).
test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)
	$(BUILD)/bin/pipeline pipeline/studies/paper.yaml --profile quick --out $(BUILD)/smoke -j $(JOBS)
	$(BUILD)/bin/validate --results $(BUILD)/smoke --references reference_data/paper.yaml \
	  --out $(BUILD)/smoke/validation --profile quick
	$(BUILD)/bin/pipeline pipeline/studies/stability.yaml --profile quick --out $(BUILD)/smoke-stability -j $(JOBS)
	$(BUILD)/bin/compare-runs stability $(BUILD)/smoke-stability $(BUILD)/smoke-stability/report

# The long kill tests: a run killed 20 times and a study killed 5 times at random
# moments, resumed from checkpoints and compared bit for bit with uninterrupted ones.
KILLS ?= 20
kill-test: build
	tests/kill/kill_test.sh $(BUILD)/bin/dem $(KILLS) $(BUILD)/kill-test/run-long
	tests/kill/study_kill_test.sh $(BUILD)/bin 5 $(BUILD)/kill-test/study-long

# The pipeline's SLURM executor against a real one-node SLURM that tests/slurm/start_cluster.sh
# starts on this machine (installing munge and SLURM's daemons if missing) and stops afterwards:
# results bit for bit the local executor's, a cancelled job resumed from its checkpoint, jobs
# adopted by a restarted pipeline, Ctrl-C cancelling them, a requeued job resumed (about 50 s; also
# part of make test, run alone).
slurm-test: build
	tests/slurm/slurm_test.sh $(BUILD)/bin $(BUILD)/slurm-test

# The input readers (scene, study, CSV, HDF5 state, checkpoints) and the rest of the unit tests that read input,
# built with AddressSanitizer and UndefinedBehaviorSanitizer; any finding fails (CI runs this).
SANITIZE_TAGS := config csv state input io result checkpoint
empty :=
comma := ,
SANITIZE_FILTER := $(subst $(empty) $(empty),$(comma),$(foreach t,$(SANITIZE_TAGS),[$(t)]))
# -O1 with line tables only (enough for the sanitizers' stack traces), assertions on: with
# RelWithDebInfo's -O2 -g this target took 1,019 of CI's 2,081 s on the 2-core VM, now 496 s
# (docs/performance.md, CI).
SANITIZE_FLAGS := -O1 -g1
sanitize: deps
	cmake -S . -B $(BUILD)-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$(SANITIZE_FLAGS)" \
	  -DDEM_SANITIZE=ON -DDEM_SANITIZE_TAGS="$(SANITIZE_TAGS)" >/dev/null
	cmake --build $(BUILD)-sanitize -j $(JOBS) --target dem_input_tests
	ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 OMP_NUM_THREADS=1 \
	  $(BUILD)-sanitize/bin/dem_input_tests "$(SANITIZE_FILTER)"

# The engine built with clang (Debian's clang 14 and libomp-dev, installed if missing) and the unit
# tests of what clang compiles its own way: the vectorised kernels and the contact laws, the cell and
# the neighbour lists (tests/CMakeLists.txt, dem_kernel_tests), without the thread-count and skin
# invariance tests (make test runs them with GCC). CI runs this after make sanitize.
clang-test: deps
	@dpkg -s clang libomp-dev >/dev/null 2>&1 || { $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get update -qq && \
	  $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends clang libomp-dev; }
	cmake -S . -B $(BUILD)-clang -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Release >/dev/null
	cmake --build $(BUILD)-clang -j $(JOBS) --target dem_kernel_tests
	OMP_NUM_THREADS=1 $(BUILD)-clang/bin/dem_kernel_tests "~[threads]"

# libFuzzer on the scene YAML, study YAML and particle CSV readers (clang), FUZZ_SECONDS each;
# crashes are written to build-fuzz/crashes. Corpora start from the project's own files.
FUZZ_SECONDS ?= 60
fuzz: deps
	@dpkg -s clang libomp-dev >/dev/null 2>&1 || { $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get update -qq && \
	  $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends clang libomp-dev; }
	cmake -S . -B $(BUILD)-fuzz -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
	  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DDEM_FUZZ=ON >/dev/null
	cmake --build $(BUILD)-fuzz -j $(JOBS) --target fuzz_scene fuzz_study fuzz_csv
	mkdir -p $(BUILD)-fuzz/crashes $(BUILD)-fuzz/corpus/scene $(BUILD)-fuzz/corpus/study $(BUILD)-fuzz/corpus/csv
	cp scenes/*.yaml scenes/tests/*.yaml $(BUILD)-fuzz/corpus/scene/
	cp pipeline/studies/*.yaml $(BUILD)-fuzz/corpus/study/
	printf 'x,y,z,radius\n0.01,0.01,0.01,0.002\n0.02,0.01,0.01,0.002\n' > $(BUILD)-fuzz/corpus/csv/two.csv
	for t in scene study csv; do \
	  $(BUILD)-fuzz/bin/fuzz_$$t $(BUILD)-fuzz/corpus/$$t -max_total_time=$(FUZZ_SECONDS) -timeout=10 \
	    -artifact_prefix=$(BUILD)-fuzz/crashes/$$t- -print_final_stats=1 > $(BUILD)-fuzz/$$t.log 2>&1; rc=$$?; \
	  tail -n 14 $(BUILD)-fuzz/$$t.log; [ $$rc = 0 ] || { echo "fuzz_$$t found a bug: $(BUILD)-fuzz/$$t.log"; exit 1; }; \
	done

# Speed of the engine (1 and 2 threads, and two runs at once) and of LAMMPS on the same packings
# (medians of 7 repetitions of 5,000 steps; the 2-thread figure moves with the VM: see README),
# then the cost against size, 8,000 to 1,000,000 spheres (reports/bench/run_bench.sh, SIZE_PLAN;
# about a quarter of an hour in all) -> reports/bench.{json,md}.
bench: build
	@dpkg -s lammps >/dev/null 2>&1 || { echo "installing: lammps (for the side-by-side benchmark)"; \
	  $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get update -qq && \
	  $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends lammps; }
	reports/bench/run_bench.sh $(BUILD) reports

# The studies through the pipeline, reusing finished results: the paper's (every density
# x test), the stability matrix and CELL_STUDIES, in one call so that they share the cores (one
# study's runs fill them while another's last runs finish). The convergence study (about 3.6
# core-hours by its plan) is `make convergence`'s; the report draws its section from its
# committed summary until then.
study: tools
	$(BUILD)/bin/pipeline pipeline/studies/paper.yaml \
	  pipeline/studies/stability.yaml $(CELL_STUDIES) --profile paper -j $(JOBS) $(if $(strip $(EXECUTOR)),--executor $(strip $(EXECUTOR)))

# Error against run time (pipeline/studies/convergence.yaml: Δt, stress rate and size on both
# sides of the paper's settings, loose and dense, 3 samples each), then its section and summary
# (reports/convergence/, committed: summary.json is what later reports read).
convergence: tools
	$(BUILD)/bin/pipeline pipeline/studies/convergence.yaml --profile paper -j $(JOBS) $(if $(strip $(EXECUTOR)),--executor $(strip $(EXECUTOR)))
	$(MAKE) --no-print-directory convergence-report

# The same with the quick profile (1,000 spheres, at most 2 cycles per repeat block), validated
# and drawn into build/quick-report (reports/ is kept for the full study).
quick: build
	$(BUILD)/bin/pipeline pipeline/studies/paper.yaml --profile quick -j $(JOBS)
	-$(BUILD)/bin/validate --results results/study/quick --references reference_data/paper.yaml \
	  --out $(BUILD)/quick-report --profile quick
	$(BUILD)/bin/ensemble-cycles results/study/quick $(BUILD)/quick-report/figures/ensemble
	reports/make_figures.sh $(BUILD)/bin results/study/quick $(BUILD)/quick-report/figures $(strip $(SAMPLE))
	-$(BUILD)/bin/figure-data samples-table results/study/quick --references reference_data/paper.yaml --per-sample \
	  > $(BUILD)/quick-report/samples.md
	$(BUILD)/bin/report --results results/study/quick --references reference_data/paper.yaml --out $(BUILD)/quick-report \
	  --profile quick --sample $(strip $(SAMPLE)) $(REPORT_SOURCE)
	reports/render_html.sh $(BUILD)/quick-report/index.md $(BUILD)/quick-report/index.html

# Validation table, figures, the convergence, stability, critical-state and liquefaction sections
# and reports/index.md from the results of the full studies (a section whose study has not run
# says so; a missing or unfinished one does not fail the report). build/bin/report writes
# index.md from reports/templates/ and computes every number in its prose (validation/report/);
# reports/render_html.sh renders it into reports/index.html (cmark-gfm), the page a referee opens;
# BASELINE is an earlier baseline's validation.json it compares every row with. A section whose
# stamp is another baseline or engine source than the paper study's makes report refuse (exit 1,
# naming it and how to run it again); OTHER_SECTIONS=--allow-other-baseline keeps it instead,
# headed "⚠ from another ..." and said as a warning.
BASELINE ?= reports/baselines/orthorhombic_validation.json
OTHER_SECTIONS ?=
# The decisions files validate takes the rows' causes from: the decisions study's and the readings'.
VALIDATION_DECISIONS = --decisions reports/decisions/decisions.json $$(for r in $(READINGS); do \
	    f=reports/readings/$$r/decisions.json; [ ! -f $$f ] || echo --decisions $$f; done)
REPORT_SOURCE = --source "commit $$(git rev-parse --short=12 HEAD 2>/dev/null || echo unknown)$$(git diff --quiet HEAD -- . ':!reports' 2>/dev/null || echo ' (with uncommitted changes)')"
report: tools
	-$(MAKE) --no-print-directory decisions-report
	-$(MAKE) --no-print-directory readings-report
	-$(BUILD)/bin/validate --results $(RESULTS) --references reference_data/paper.yaml --out reports $(VALIDATION_DECISIONS)
	$(BUILD)/bin/ensemble-cycles $(RESULTS) reports/figures/ensemble
	reports/make_figures.sh $(BUILD)/bin $(RESULTS) reports/figures $(strip $(SAMPLE))
	-$(BUILD)/bin/figure-data samples-table $(RESULTS) --references reference_data/paper.yaml --per-sample > reports/samples.md
	-$(MAKE) --no-print-directory convergence-report
	$(MAKE) --no-print-directory stability-report
	-$(MAKE) --no-print-directory critical-state-report
	-$(MAKE) --no-print-directory liquefaction-report
	-$(MAKE) --no-print-directory literature-report
	$(BUILD)/bin/report --results $(RESULTS) --references reference_data/paper.yaml --out reports --sample $(strip $(SAMPLE)) \
	  --baseline $(BASELINE) --decisions $(DECISIONS) --stability $(STABILITY) $(REPORT_SOURCE) $(OTHER_SECTIONS)
	reports/render_html.sh reports/index.md reports/index.html

# Published DEM values: reference_data/literature.yaml against the critical-state ensemble
# (pipeline/studies/critical_state_ensemble.yaml, also run by `make critical-state`), and
# reference_data/literature_fcc.yaml against Thornton's FCC array (pipeline/studies/fcc_thornton.yaml,
# 108 spheres, seconds); a study not run yet is said so. `literature` runs the studies first.
LITERATURE_RESULTS ?= results/critical_state_ensemble/paper
FCC_RESULTS ?= results/fcc_thornton/paper
literature: tools
	$(BUILD)/bin/pipeline pipeline/studies/critical_state_ensemble.yaml pipeline/studies/fcc_thornton.yaml --profile paper -j $(JOBS) $(if $(strip $(EXECUTOR)),--executor $(strip $(EXECUTOR)))
	$(MAKE) --no-print-directory literature-report
literature-report: tools
	@if [ -f $(LITERATURE_RESULTS)/runs.tsv ]; then mkdir -p reports/literature && \
	  $(BUILD)/bin/validate --results $(LITERATURE_RESULTS) --references reference_data/literature.yaml --out reports/literature; \
	elif [ -f reports/literature/validation.json ]; then echo "literature: no results in $(LITERATURE_RESULTS); judged again from reports/literature/validation.json"; \
	  $(BUILD)/bin/validate --from-json reports/literature/validation.json --references reference_data/literature.yaml --out reports/literature; \
	else echo "literature: no results in $(LITERATURE_RESULTS) yet (make literature)"; fi
	@if [ -f $(FCC_RESULTS)/runs.tsv ]; then mkdir -p reports/literature/fcc && \
	  $(BUILD)/bin/validate --results $(FCC_RESULTS) --references reference_data/literature_fcc.yaml --out reports/literature/fcc; \
	else echo "literature: no results in $(FCC_RESULTS) yet (make literature)"; fi

# The report from the studies that are here, on a machine without the paper study's results (after
# running one study: make critical-state, make literature, ...): the verdicts judged again from the
# committed reports/validation.json, and what the text takes from the paper study's results read
# back from reports/study_values.json, which the last report written with them left.
report-sections: tools
	-$(MAKE) --no-print-directory decisions-report
	-$(MAKE) --no-print-directory readings-report
	-$(MAKE) --no-print-directory critical-state-report
	-$(MAKE) --no-print-directory liquefaction-report
	-$(MAKE) --no-print-directory convergence-report
	-$(MAKE) --no-print-directory literature-report
	@if [ -f $(RESULTS)/runs.tsv ]; then \
	  $(BUILD)/bin/validate --results $(RESULTS) --references reference_data/paper.yaml --out reports $(VALIDATION_DECISIONS); \
	else $(BUILD)/bin/validate --from-json reports/validation.json --references reference_data/paper.yaml --out reports $(VALIDATION_DECISIONS); fi || true
	$(BUILD)/bin/report --results $(RESULTS) --references reference_data/paper.yaml --out reports --sample $(strip $(SAMPLE)) \
	  --baseline $(BASELINE) --decisions $(DECISIONS) --stability $(STABILITY) $(REPORT_SOURCE) $(OTHER_SECTIONS)
	reports/render_html.sh reports/index.md reports/index.html

# The paper's open choices (docs/method.md#open-choices): each reading one at a time from the baseline, 3
# samples of 1,000 spheres (pipeline/studies/decisions.yaml), then the report's section on them.
decisions: tools
	$(BUILD)/bin/pipeline pipeline/studies/decisions.yaml --profile paper -j $(JOBS) $(if $(strip $(EXECUTOR)),--executor $(strip $(EXECUTOR)))
	$(MAKE) --no-print-directory report

# The decisions section from the decisions study's results; without them, re-drawn from its
# findings (reports/decisions/decisions.json: shifts restated, the size check left out and said
# so); neither: a study not run yet is said so.
decisions-report: tools
	@if [ -f $(DECISIONS)/runs.tsv ]; then \
	  $(BUILD)/bin/compare-runs decisions $(DECISIONS) reports/decisions --references reference_data/paper.yaml --ensemble $(RESULTS) \
	    --draw reports/gnuplot; \
	elif [ -f reports/decisions/decisions.json ]; then \
	  echo "decisions: no results in $(DECISIONS); re-drawing from reports/decisions/decisions.json"; \
	  $(BUILD)/bin/compare-runs decisions --from-json reports/decisions/decisions.json reports/decisions --references reference_data/paper.yaml \
	    --draw reports/gnuplot; \
	else echo "decisions: no results in $(DECISIONS) yet (make decisions)"; fi

# The readings that explain the misses, measured again at the paper's size (8,000 spheres; the
# studies pipeline/studies/readings_<name>.yaml, run with build/bin/pipeline ... --profile paper):
# each reading against the paper study's samples of the same seeds (--baseline-results), judged
# on its full ensemble, into reports/readings/<name>/. A study not run yet is said so and skipped;
# a run not finished leaves its reading not judged on the rows that read it. validate (make
# report) takes each row's cause from the largest size that judged it.
readings-report: tools
	@for r in $(READINGS); do \
	  dir=results/readings_$$r/paper; \
	  if [ -f $$dir/runs.tsv ]; then \
	    $(BUILD)/bin/compare-runs decisions $$dir reports/readings/$$r --references reference_data/paper.yaml \
	      --baseline-results $(RESULTS) --ensemble $(RESULTS) --draw reports/gnuplot; \
	  else echo "readings: no results in $$dir yet (build/bin/pipeline pipeline/studies/paper.yaml pipeline/studies/readings_$$r.yaml --profile paper: with the paper study in the same call, its samples are copied)"; fi; \
	done

# Drained shear at constant p of the dense sample to the critical state, compression and
# extension against the shearing friction and the b series (pipeline/studies/critical_state.yaml),
# μ = 0.5 on 3 samples (critical_state_ensemble.yaml) and μ = 0 and 0.5 at two slower rates
# (critical_state_rates.yaml), in one call so that they share the cores, then its section
# (reports/critical_state/: table, friction angles with the ensemble's sd and the quasi-static
# limit, e and CN, the pi-plane, q/p against sqrt(I)).
critical-state: tools
	$(BUILD)/bin/pipeline pipeline/studies/critical_state.yaml pipeline/studies/critical_state_ensemble.yaml \
	  pipeline/studies/critical_state_rates.yaml --profile paper -j $(JOBS) $(if $(strip $(EXECUTOR)),--executor $(strip $(EXECUTOR)))
	$(MAKE) --no-print-directory critical-state-report

# Undrained cyclic triaxial tests of the loose and the medium sample to liquefaction, and their
# unloaded holds, on 3 samples each (pipeline/studies/liquefaction_{loose,medium}.yaml, in one
# call with the paper study, whose samples they shear: copied, not prepared again), then their section (reports/liquefaction/: per density and CSR the median N_L over the
# samples with its range, every test, CSR against N_L, r_u against cycles).
liquefaction: tools
	$(BUILD)/bin/pipeline pipeline/studies/paper.yaml pipeline/studies/liquefaction_loose.yaml pipeline/studies/liquefaction_medium.yaml --profile paper \
	  -j $(JOBS) $(if $(strip $(EXECUTOR)),--executor $(strip $(EXECUTOR)))
	$(MAKE) --no-print-directory liquefaction-report

# Each section another study feeds, from that study's results (compare-runs, its figures drawn with
# --draw reports/gnuplot); a study not run yet is said so. The convergence section without its
# results is re-drawn from its committed summary.json; the critical state's ensemble and rates are
# added when they have run.
convergence-report: tools
	$(BUILD)/bin/compare-runs convergence $(CONVERGENCE) reports/convergence --threads 1 --draw reports/gnuplot \
	  $$([ ! -f reports/validation.json ] || echo --validation reports/validation.json)
stability-report: tools
	@if [ -f $(STABILITY)/runs.tsv ]; then $(BUILD)/bin/compare-runs stability $(STABILITY) reports/stability --report-only; \
	else echo "stability: no results in $(STABILITY) yet (make study)"; fi
critical-state-report: tools
	@if [ -f $(CRITICAL_STATE)/runs.tsv ]; then \
	  $(BUILD)/bin/compare-runs critical-state $(CRITICAL_STATE) reports/critical_state --draw reports/gnuplot \
	    $$([ ! -f $(CRITICAL_STATE_ENSEMBLE)/runs.tsv ] || echo --ensemble $(CRITICAL_STATE_ENSEMBLE)) \
	    $$([ ! -f $(CRITICAL_STATE_RATES)/runs.tsv ] || echo --rates $(CRITICAL_STATE_RATES) --references reference_data/literature.yaml); \
	else echo "critical-state: no results in $(CRITICAL_STATE) yet (make critical-state)"; fi
liquefaction-report: tools
	@folders="$$(for d in $(LIQUEFACTION); do [ ! -f $$d/runs.tsv ] || echo $$d; done)"; \
	if [ -n "$$folders" ]; then $(BUILD)/bin/compare-runs liquefaction reports/liquefaction $$folders --draw reports/gnuplot; \
	else echo "liquefaction: no results in $(LIQUEFACTION) yet (make liquefaction)"; fi

# The samples before shearing (pipeline/studies/samples.yaml): the three preparation scenes at
# full size, 3 seeds, viscous and local damping (18 runs of 8,000 spheres), then the table of them
# beside the paper's values (reports/samples/table.md).
samples: tools
	$(BUILD)/bin/pipeline pipeline/studies/samples.yaml --profile paper -j $(JOBS) $(if $(strip $(EXECUTOR)),--executor $(strip $(EXECUTOR)))
	$(BUILD)/bin/figure-data samples-table results/samples/paper --references reference_data/paper.yaml > reports/samples/table.md

# The sample study: the same at 1,000 spheres too, and the preparation protocol's free choices one
# at a time (pipeline/studies/sweep.yaml), in one pipeline call; the tables table.md and sweep.md.
samples-study: tools
	$(BUILD)/bin/pipeline pipeline/studies/samples.yaml pipeline/studies/sweep.yaml --profile paper -j $(JOBS) $(if $(strip $(EXECUTOR)),--executor $(strip $(EXECUTOR)))
	$(BUILD)/bin/pipeline pipeline/studies/samples.yaml --profile quick -j $(JOBS) $(if $(strip $(EXECUTOR)),--executor $(strip $(EXECUTOR)))
	$(BUILD)/bin/figure-data samples-table results/samples/quick results/samples/paper --references reference_data/paper.yaml > reports/samples/table.md
	$(BUILD)/bin/figure-data samples-table results/sweep/paper --references reference_data/paper.yaml --baseline base > reports/samples/sweep.md

# The five cyclic tests on the full-size samples are the paper study's (make study); their table
# (steps, wall time, tracking error, eps_v and CN at cycle ends) for one sample.
cyclic-tests: study
	$(BUILD)/bin/figure-data tests-table $(RESULTS)/$(strip $(SAMPLE)) > reports/samples/tests.md

# A result's XDMF view opened in ParaView (pvbatch; paraview and xvfb installed by the target, a
# virtual display started if there is none) and its spheres rendered to a PNG the report shows
# (about 20 s; not in make test: ParaView is a large install).
RENDER ?= $(RESULTS)/$(strip $(SAMPLE))/dense_prepare.xdmf
render: tools
	reports/render/render.sh $(RENDER) reports/figures/render_dense_prepare.png "dense sample $(strip $(SAMPLE)), after isotropic compression"
	@mkdir -p $(BUILD)/render
	$(BUILD)/bin/dem run scenes/examples/triaxial_compression.yaml --out $(BUILD)/render/triaxial.h5 --force --quiet --threads 1 \
	  --set 'stages[0].until.strain=0.02' --set output.frames.interval=2000 --set output.frames.contacts=true
	reports/render/render.sh $(BUILD)/render/triaxial.xdmf reports/figures/render_triaxial_contacts.png \
	  "drained triaxial compression of the shipped 1,000-sphere dense sample, last frame with contacts"

clean:
	rm -rf $(BUILD)
