# cyclic-triax: `make all` and `make test`; every target a few calls of the tools (docs/make-targets.md).
BUILD    ?= build
JOBS     ?= $(shell nproc 2>/dev/null || echo 2)
# python3-*: the README's Python lines, tests/clients/ and python/ (its tests, its notebook); cmark-gfm: index.html.
PACKAGES := g++ cmake make libeigen3-dev libhdf5-dev libyaml-cpp-dev catch2 gnuplot-nox hdf5-tools libboost-math-dev libboost-dev libcli11-dev nlohmann-json3-dev python3-h5py python3-pandas \
            pybind11-dev python3-dev python3-numpy python3-yaml python3-pytest jupyter-nbconvert python3-ipykernel cmark-gfm
SUDO     := $(shell [ "$$(id -u)" = 0 ] || echo sudo)
# $(call INSTALL,packages): the Debian packages of the list that are missing, installed (non-interactive).
INSTALL = missing=""; for p in $(1); do dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; if [ -z "$$missing" ]; \
  then echo "packages: all present"; else echo "installing:$$missing"; $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get update -qq && \
  $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $$missing; fi

RESULTS  ?= results/study/paper
SAMPLE   ?= seed1                       # the sample whose runs the single-run figures show
CONVERGENCE ?= results/convergence/paper
STABILITY   ?= results/stability/paper
DECISIONS   ?= results/decisions/paper
# The readings at the paper's size: pipeline/studies/readings_<name>.yaml (docs/make-targets.md).
READINGS    ?= loose medium_dense dashpot
CRITICAL_STATE ?= results/critical_state/paper
CRITICAL_STATE_ENSEMBLE ?= results/critical_state_ensemble/paper
CRITICAL_STATE_RATES    ?= results/critical_state_rates/paper
LIQUEFACTION   ?= results/liquefaction_loose/paper results/liquefaction_medium/paper
# What `make study` runs besides the paper and stability studies (the ensembles: their own targets).
CELL_STUDIES   ?= pipeline/studies/critical_state.yaml
EXECUTOR    ?=                          # local or slurm (pipeline --executor); empty: the study files' executor key, else local

PIPELINE  = $(BUILD)/bin/pipeline
STUDIES   = $(PIPELINE) --profile paper -j $(JOBS) $(if $(strip $(EXECUTOR)),--executor $(strip $(EXECUTOR)))
VALIDATE  = $(BUILD)/bin/validate --references reference_data/paper.yaml
SECTION   = $(BUILD)/bin/compare-runs
DRAW      = --draw reports/gnuplot
TABLES    = $(BUILD)/bin/figure-data samples-table
# The decisions files validate takes the rows' causes from (a study not run yet has none: skipped).
VALIDATION_DECISIONS = --decisions reports/decisions/decisions.json $(foreach r,$(READINGS),--decisions reports/readings/$(r)/decisions.json)
# BASELINE: an earlier baseline's validation.json, compared row by row. A section from another baseline or
# engine source than the paper study's makes report refuse (exit 1); OTHER_SECTIONS=--allow-other-baseline keeps it.
BASELINE ?= reports/baselines/orthorhombic_validation.json
OTHER_SECTIONS ?=
REPORT    = $(BUILD)/bin/report --references reference_data/paper.yaml --sample $(strip $(SAMPLE))
REPORT_ALL = $(REPORT) --baseline $(BASELINE) --decisions $(DECISIONS) --stability $(STABILITY) $(OTHER_SECTIONS)
# A calibration report's figures, drawn in its folder ($(1)).
CALIBRATION_FIGURES = cd $(1) && GNUPLOT_LIB=$(CURDIR)/reports/gnuplot gnuplot $(CURDIR)/reports/gnuplot/calibration.gp

.PHONY: all deps build tools examples example-samples install test kill-test slurm-test sanitize clang-test fuzz bench quick study convergence report decisions decisions-report convergence-report stability-report critical-state-report liquefaction-report readings-report report-sections literature literature-report critical-state liquefaction samples samples-study cyclic-tests render calibration-demo calibration-two-sizes calibration-example open-choices open-choices-check open-choices-paper-size clean

# Everything: install, build, run the full study, validate it, draw the figures, write reports/index.md (fails on a must-pass row).
all: deps tools study report
	$(VALIDATE) --results $(RESULTS) --out reports

deps:
	@$(call INSTALL,$(PACKAGES))
build: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null
	cmake --build $(BUILD) -j $(JOBS)

# Only what the studies and the report use (from nothing, 1 min 11 s instead of 2 min 38 s here).
TOOLS := dem pipeline validate compare-runs ensemble-cycles figure-data report calibrate python_module
tools: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null
	cmake --build $(BUILD) -j $(JOBS) --target $(TOOLS)

examples: tools
	@mkdir -p $(BUILD)/examples
	@for s in scenes/examples/*.yaml; do echo "== $$s"; OMP_NUM_THREADS=1 $(BUILD)/bin/dem run $$s \
	  --out $(BUILD)/examples/$$(basename $$s .yaml).h5 --threads 1 --no-resume --force --quiet || exit 1; done
# The shipped samples, scenes/samples/{loose,medium,dense}_1k.h5 (tests/examples/samples_test.sh checks them).
example-samples: tools
	@for d in loose medium dense; do OMP_NUM_THREADS=1 $(BUILD)/bin/dem run scenes/prepare_$$d.yaml --set 'particles.lattice.n=[10, 10, 10]' \
	  --out scenes/samples/$${d}_1k.h5 --threads 1 --no-resume --force --quiet && rm -f scenes/samples/$${d}_1k.xdmf || exit 1; done

# Calibrations (docs/calibration.md). A demonstration with a known answer: calibration_truth.yaml's
# profile $(2) makes the lab curves of calibration $(1). calibration-two-sizes: lab at 8,000 spheres,
# sets at 1,000 and 8,000, and the same fitted at 1,000 alone.
CAL_POINTS := 0.0002,0.0005,0.001,0.002,0.005,0.01,0.02,0.04,0.07
define CALIBRATION_DEMO
	$(PIPELINE) pipeline/studies/calibration_truth.yaml --profile $(2) -j $(JOBS)
	for y in q_over_p volumetric_strain; do $(BUILD)/bin/calibrate lab-curve --x strain_3 --y $$y --at $(CAL_POINTS) --out \
	  reference_data/calibration/$(1)_$$y.csv $(foreach s,11 12 13 14 15,results/calibration/$(2)/seed$(s)/truth_dense_triaxial.h5) || exit 1; done
	$(BUILD)/bin/calibrate truth pipeline/calibrations/$(1).yaml results/calibration/$(2)/seed11/truth_dense_triaxial.h5 --out reports/calibration/$(1)/truth.json
	$(BUILD)/bin/calibrate pipeline/calibrations/$(1).yaml -j $(JOBS) --truth reports/calibration/$(1)/truth.json
	$(call CALIBRATION_FIGURES,reports/calibration/$(1))
endef
calibration-demo: tools
	$(call CALIBRATION_DEMO,synthetic_triaxial,paper)
calibration-two-sizes: tools
	$(call CALIBRATION_DEMO,synthetic_two_sizes,large)
	$(BUILD)/bin/calibrate truth pipeline/calibrations/synthetic_one_size.yaml results/calibration/large/seed11/truth_dense_triaxial.h5 --out reports/calibration/synthetic_one_size/truth.json
	$(BUILD)/bin/calibrate pipeline/calibrations/synthetic_one_size.yaml -j $(JOBS) --truth reports/calibration/synthetic_one_size/truth.json
	$(call CALIBRATION_FIGURES,reports/calibration/synthetic_one_size)
OPEN := pipeline/calibrations/paper_open_choices.yaml
OPEN_REPORT := reports/calibration/paper_open_choices
open-choices: tools
	$(BUILD)/bin/calibrate $(OPEN) -j $(JOBS)
	$(call CALIBRATION_FIGURES,$(OPEN_REPORT))
open-choices-check: tools
	$(PIPELINE) new pipeline/studies/calibration_paper_best.yaml --from pipeline/studies/calibration_paper.yaml --force \
	  --output results/calibration_paper_best --variant "$$($(BUILD)/bin/calibrate variant $(OPEN))"
	$(PIPELINE) pipeline/studies/calibration_paper_best.yaml --profile check -j $(JOBS)
	$(VALIDATE) --results results/calibration_paper_best/check --out $(OPEN_REPORT)/best
open-choices-paper-size: tools
	$(PIPELINE) pipeline/studies/open_choices_paper_size.yaml -j $(JOBS)
	$(VALIDATE) --results results/open_choices_paper_size/paper --densities medium dense \
	  --borrow loose:contact_dashpots:reports/readings/dashpot/decisions.json --out $(OPEN_REPORT)/paper_size
calibration-example: tools
	$(BUILD)/bin/calibrate examples/calibration/calibration.yaml -j $(JOBS)
	$(call CALIBRATION_FIGURES,results/calibration_example/report)

PREFIX ?= /usr/local
install: tools
	cmake --install $(BUILD) --prefix $(PREFIX)
# Unit tests, then a smoke run of the pipeline (quick profile) and of the stability matrix.
test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)
	$(PIPELINE) pipeline/studies/paper.yaml --profile quick --out $(BUILD)/smoke -j $(JOBS)
	$(VALIDATE) --results $(BUILD)/smoke --out $(BUILD)/smoke/validation --profile quick
	$(PIPELINE) pipeline/studies/stability.yaml --profile quick --out $(BUILD)/smoke-stability -j $(JOBS)
	$(SECTION) stability $(BUILD)/smoke-stability $(BUILD)/smoke-stability/report

KILLS ?= 20
kill-test: build
	tests/kill/kill_test.sh $(BUILD)/bin/dem $(KILLS) $(BUILD)/kill-test/run-long
	tests/kill/study_kill_test.sh $(BUILD)/bin 5 $(BUILD)/kill-test/study-long
slurm-test: build
	tests/slurm/slurm_test.sh $(BUILD)/bin $(BUILD)/slurm-test
# The input readers' tests with ASan and UBSan, at -O1 -g1 (496 s on CI's VM; -O2 -g: 1,019 s).
SANITIZE_TAGS := config csv state input io result checkpoint
SANITIZE_FILTER := $(shell printf '[%s],' $(SANITIZE_TAGS) | sed 's/,$$//')
sanitize: deps
	cmake -S . -B $(BUILD)-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
	  -DDEM_SANITIZE=ON -DDEM_SANITIZE_TAGS="$(SANITIZE_TAGS)" >/dev/null
	cmake --build $(BUILD)-sanitize -j $(JOBS) --target dem_input_tests
	ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 OMP_NUM_THREADS=1 $(BUILD)-sanitize/bin/dem_input_tests "$(SANITIZE_FILTER)"
# The unit tests of what clang compiles its own way (dem_kernel_tests; [threads]: make test's).
clang-test: deps
	@$(call INSTALL,clang libomp-dev)
	cmake -S . -B $(BUILD)-clang -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Release >/dev/null
	cmake --build $(BUILD)-clang -j $(JOBS) --target dem_kernel_tests
	OMP_NUM_THREADS=1 $(BUILD)-clang/bin/dem_kernel_tests "~[threads]"
# libFuzzer on the scene YAML, study YAML and particle CSV readers, FUZZ_SECONDS each.
FUZZ_SECONDS ?= 60
fuzz: deps
	@$(call INSTALL,clang libomp-dev)
	cmake -S . -B $(BUILD)-fuzz -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo -DDEM_FUZZ=ON >/dev/null
	cmake --build $(BUILD)-fuzz -j $(JOBS) --target fuzz_scene fuzz_study fuzz_csv
	tests/fuzz/run_fuzz.sh $(BUILD)-fuzz $(FUZZ_SECONDS)
# The engine's speed against LAMMPS and against size (a quarter of an hour): reports/bench.{json,md}.
bench: build
	@$(call INSTALL,lammps)
	reports/bench/run_bench.sh $(BUILD) reports
# The studies, reusing finished results, in one call so that they share the cores.
study: tools
	$(STUDIES) pipeline/studies/paper.yaml pipeline/studies/stability.yaml $(CELL_STUDIES)
convergence: tools
	$(STUDIES) pipeline/studies/convergence.yaml
	$(MAKE) --no-print-directory convergence-report
# The paper study with the quick profile, validated and drawn into build/quick-report.
QUICK := results/study/quick
quick: build
	$(PIPELINE) pipeline/studies/paper.yaml --profile quick -j $(JOBS)
	-$(VALIDATE) --results $(QUICK) --out $(BUILD)/quick-report --profile quick
	$(BUILD)/bin/ensemble-cycles $(QUICK) $(BUILD)/quick-report/figures/ensemble
	reports/make_figures.sh $(BUILD)/bin $(QUICK) $(BUILD)/quick-report/figures $(strip $(SAMPLE))
	-$(TABLES) $(QUICK) --references reference_data/paper.yaml --per-sample > $(BUILD)/quick-report/samples.md
	$(REPORT) --results $(QUICK) --out $(BUILD)/quick-report --profile quick
	reports/render_html.sh $(BUILD)/quick-report/index.md $(BUILD)/quick-report/index.html
# Validation table, figures, every section another study feeds, then reports/index.md and its web
# page (a section whose study has not run here keeps its committed tables, and says so).
report: tools stability-report
	-$(MAKE) --no-print-directory -k decisions-report readings-report
	-$(VALIDATE) --results $(RESULTS) --out reports $(VALIDATION_DECISIONS)
	$(BUILD)/bin/ensemble-cycles $(RESULTS) reports/figures/ensemble
	reports/make_figures.sh $(BUILD)/bin $(RESULTS) reports/figures $(strip $(SAMPLE))
	-$(TABLES) $(RESULTS) --references reference_data/paper.yaml --per-sample > reports/samples.md
	-$(MAKE) --no-print-directory -k convergence-report critical-state-report liquefaction-report literature-report
	$(REPORT_ALL) --results $(RESULTS) --out reports
	reports/render_html.sh reports/index.md reports/index.html
# The report without the paper study's results: verdicts judged again from reports/validation.json, values from study_values.json.
report-sections: tools
	-$(MAKE) --no-print-directory -k decisions-report readings-report critical-state-report liquefaction-report literature-report
	-$(VALIDATE) --results $(RESULTS) --out reports --without-results redraw $(VALIDATION_DECISIONS)
	-$(MAKE) --no-print-directory convergence-report
	$(REPORT_ALL) --results $(RESULTS) --out reports
	reports/render_html.sh reports/index.md reports/index.html

# Published DEM values against the critical-state ensemble and Thornton's FCC array.
LITERATURE_RESULTS ?= results/critical_state_ensemble/paper
FCC_RESULTS ?= results/fcc_thornton/paper
literature: tools
	$(STUDIES) pipeline/studies/critical_state_ensemble.yaml pipeline/studies/fcc_thornton.yaml
	$(MAKE) --no-print-directory literature-report
literature-report: tools
	$(BUILD)/bin/validate --results $(LITERATURE_RESULTS) --references reference_data/literature.yaml --out reports/literature --without-results redraw
	$(BUILD)/bin/validate --results $(FCC_RESULTS) --references reference_data/literature_fcc.yaml --out reports/literature/fcc --without-results redraw

# The paper's open choices, one reading at a time on 3 samples of 1,000 spheres, then the report.
decisions: tools
	$(STUDIES) pipeline/studies/decisions.yaml
	$(MAKE) --no-print-directory report
# Each section another study feeds (compare-runs, docs/make-targets.md): from the study's results;
# without them, decisions and convergence re-drawn from their committed summaries, the others kept.
decisions-report: tools
	$(SECTION) decisions $(DECISIONS) reports/decisions --references reference_data/paper.yaml --ensemble $(RESULTS) $(DRAW) \
	  --without-results redraw --ensemble-json reports/validation.json
readings-report: tools
	@for r in $(READINGS); do $(SECTION) decisions results/readings_$$r/paper reports/readings/$$r --references reference_data/paper.yaml \
	  --baseline-results $(RESULTS) --ensemble $(RESULTS) $(DRAW) --without-results keep || exit 1; done
convergence-report: tools
	$(SECTION) convergence $(CONVERGENCE) reports/convergence --threads 1 $(DRAW) --without-results redraw \
	  $$([ ! -f reports/validation.json ] || echo --validation reports/validation.json)
stability-report: tools
	$(SECTION) stability $(STABILITY) reports/stability --report-only --without-results redraw
critical-state-report: tools
	$(SECTION) critical-state $(CRITICAL_STATE) reports/critical_state $(DRAW) --ensemble $(CRITICAL_STATE_ENSEMBLE) \
	  --rates $(CRITICAL_STATE_RATES) --references reference_data/literature.yaml --without-results keep
liquefaction-report: tools
	$(SECTION) liquefaction reports/liquefaction $(LIQUEFACTION) $(DRAW) --without-results keep

# One study alone, then its section (liquefaction with the paper study, whose samples it shears).
critical-state: tools
	$(STUDIES) pipeline/studies/critical_state.yaml pipeline/studies/critical_state_ensemble.yaml pipeline/studies/critical_state_rates.yaml
	$(MAKE) --no-print-directory critical-state-report
liquefaction: tools
	$(STUDIES) pipeline/studies/paper.yaml pipeline/studies/liquefaction_loose.yaml pipeline/studies/liquefaction_medium.yaml
	$(MAKE) --no-print-directory liquefaction-report

# The samples before shearing and their tables (samples-study: also 1,000 spheres and the sweep).
samples: tools
	$(STUDIES) pipeline/studies/samples.yaml
	$(TABLES) results/samples/paper --references reference_data/paper.yaml > reports/samples/table.md
samples-study: tools
	$(STUDIES) pipeline/studies/samples.yaml pipeline/studies/sweep.yaml
	$(PIPELINE) pipeline/studies/samples.yaml --profile quick -j $(JOBS) $(if $(strip $(EXECUTOR)),--executor $(strip $(EXECUTOR)))
	$(TABLES) results/samples/quick results/samples/paper --references reference_data/paper.yaml > reports/samples/table.md
	$(TABLES) results/sweep/paper --references reference_data/paper.yaml --baseline base > reports/samples/sweep.md

cyclic-tests: study
	$(BUILD)/bin/figure-data tests-table $(RESULTS)/$(strip $(SAMPLE)) > reports/samples/tests.md
# A result rendered by ParaView, then a short triaxial compression with its contacts.
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
