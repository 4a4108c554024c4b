# mortarcontact — one-command set-up, build, demo, tests and benchmarks (run as root on Debian).
PYTHON ?= python3
JOBS ?= $(shell nproc)
BUILD_DIR := build/cmake
# The core set (build, gmsh's runtime libraries, lint). Recommended packages are not installed:
# none is needed, and they doubled the count. Into a Debian 12 minbase: 157 packages, 170 MB,
# 166 s (all 20 with recommends, as before: 376 packages, 431 MB, 387 s).
DEBS := g++ cmake ninja-build ccache pkg-config libeigen3-dev libsuitesparse-dev libmetis-dev \
        nlohmann-json3-dev libnanoflann-dev libhdf5-dev libgtest-dev libmuparser-dev \
        libglu1-mesa libxcursor1 libxft2 libxinerama1 libopenblas0-openmp clang-format
# The PETSc/MPI/hypre/MUMPS stack of the optional PETSc linear solver plugin (`make deps-petsc`,
# then `make install` builds plugins/petsc): 127 more packages, 108 MB, 113 s.
DEBS_PETSC := petsc-dev
PY_BUILD := scikit-build-core pybind11 ninja cmake
PY_RUN := numpy scipy meshio h5py rich pytest sympy matplotlib gmsh
# The notebooks (run by the tests) and the documentation site.
PY_DOCS := jupytext nbclient ipykernel sphinx myst-parser
# ruff pinned to a minor release: new minor releases stabilise new rules of the selected families.
PY_LINT := ruff~=0.17.6
CLANG_FORMAT ?= clang-format
# The hand-written C++ (.clang-format); the generated conditions are compared byte for byte with
# their generator's output instead.
CXX_FILES := git ls-files -z -- '*.h' '*.hpp' '*.cpp' '*.cc' ':(exclude)custom_conditions/generated/*' \
             ':(exclude)tests/cases/*' ':(exclude)build/*' ':(exclude,glob)**/.venv/**'

.PHONY: all deps deps-petsc install demo docs test lint format test-cpp test-python bench bench-large bench-robustness clean \
        fuzz-deps fuzz-build fuzz sanitize-build test-sanitize

all: install

# Installs the Debian packages of $(1) that are missing.
define apt_install
	@missing=""; for p in $(1); do dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  echo "Installing Debian packages:$$missing"; \
	  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $$missing; \
	fi
endef

deps:
	$(call apt_install,$(DEBS))
	@$(PYTHON) -m pip install -q --disable-pip-version-check $(PY_BUILD) $(PY_RUN) $(PY_DOCS) '$(PY_LINT)'

# The PETSc plugin's packages; the next `make install` configures and builds the plugin.
deps-petsc:
	$(call apt_install,$(DEBS_PETSC))

# Incremental: scikit-build-core reuses $(BUILD_DIR) and ccache caches objects.
install: deps
	CMAKE_BUILD_PARALLEL_LEVEL=$(JOBS) $(PYTHON) -m pip install -q --disable-pip-version-check \
	  --no-build-isolation --no-deps .

demo: install
	cd examples/hertz_cylinder && $(PYTHON) run_demo.py

# The documentation site (Sphinx + MyST, docs/): build/docs/html/index.html; warnings are errors.
docs: install
	$(PYTHON) -m sphinx -W --keep-going -q -b html docs build/docs/html

test: install lint test-cpp test-python

# Checks only: C++ against .clang-format (clang-format 14 of Debian 12), Python against the ruff
# configuration in pyproject.toml (its import sorting included). `make format` applies both.
lint:
	$(CXX_FILES) | xargs -0 -r $(CLANG_FORMAT) --dry-run -Werror
	$(PYTHON) -m ruff check .

format:
	$(CXX_FILES) | xargs -0 -r $(CLANG_FORMAT) -i
	$(PYTHON) -m ruff check --select I --fix .

test-cpp:
	ctest --test-dir $(BUILD_DIR) --output-on-failure -j $(JOBS)

test-python:
	$(PYTHON) -m pytest -q tests/python

# Structural block (0.1M-1M DoFs), Hertz cases, the structural parity sweep and the frictional
# shared cases (Newton iterations, benchmarks/kratos_cases/frictional_iterations.md) side by side with
# Kratos 10.4 (its wheels go into a separate virtual environment created by the scripts, never
# into this one).
bench: install
	$(PYTHON) benchmarks/run_benchmarks.py
	$(PYTHON) benchmarks/hertz/compare.py --cases hertz2d_2k,hertz2d_8k,hertz2d_30k,hertz3d_15k,hertz3dgrid_15k
	$(PYTHON) benchmarks/hertz/reuse_ab.py
	$(PYTHON) benchmarks/hertz/linear_phase.py --cases hertz2d_8k,hertz2d_30k,hertz3d_15k,hertz3dgrid_15k
	$(PYTHON) benchmarks/hertz/wait_policy.py
	$(PYTHON) benchmarks/hertz/linear_solvers.py
	$(PYTHON) benchmarks/hertz/factorization_2d.py
	$(PYTHON) benchmarks/hertz/contact_scaling.py
	$(PYTHON) benchmarks/structural_parity/run.py
	$(PYTHON) benchmarks/kratos_cases/frictional_iterations.py
	$(PYTHON) benchmarks/self_contact/compare.py

# The large Hertz cases, one run each (Kratos needs about 25 minutes for hertz3d_50k alone); the
# 3D cases past 50k DoFs with ours only, on the PETSc field split (algebraic multigrid): a direct
# factorization of hertz3d_600k would need tens of GB.
FIELDSPLIT := {"solver_type": "petsc", "tolerance": 1e-8, "max_iteration": 500, "petsc_options": {"pc_type": "fieldsplit"}}
bench-large: install
	$(PYTHON) benchmarks/hertz/compare.py --cases hertz2d_100k,hertz2d_250k,hertz3d_50k --repeat 1 \
	  --output benchmarks/hertz/results_large.md --plot benchmarks/hertz/time_vs_dofs_large.png
	$(PYTHON) benchmarks/hertz/linear_solvers.py --cases hertz2d_100k,hertz3d_50k --repeat 1 \
	  --output benchmarks/hertz/results_linear_solvers_large.md
	$(PYTHON) benchmarks/hertz/compare.py --cases hertz3d_15k,hertz3d_50k,hertz3d_150k,hertz3d_600k --repeat 1 \
	  --codes mortarcontact --linear-solver '$(FIELDSPLIT)' \
	  --output benchmarks/hertz/results_3d_multigrid.md --plot benchmarks/hertz/time_vs_dofs_3d_multigrid.png

# Robustness sweep against Kratos 10.4 (issue 10): about 150 small frictionless cases, each run once
# by both codes in its own subprocess; writes benchmarks/robustness/results.md. FILTER=regex runs part.
bench-robustness: install
	$(PYTHON) benchmarks/robustness/run_sweep.py $(if $(FILTER),--filter '$(FILTER)')

# Coverage-guided fuzzing (issue 16) of the mdpa reader, the JSON settings and the function
# expressions with libFuzzer, AddressSanitizer and UndefinedBehaviorSanitizer, in build/fuzz
# (clang; never mixed with build/cmake). FUZZ_TIME seconds per target; the growing corpora stay in
# build/fuzz/corpus, seeded from tests/cases; crashes land in build/fuzz/findings/<target>/.
FUZZ_DEBS := clang libclang-rt-14-dev libomp-14-dev
FUZZ_DIR := build/fuzz
FUZZ_TIME ?= 60
FUZZ_TARGETS := mdpa parameters expression
SANITIZE_FLAGS := -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer
fuzz-deps: deps
	@missing=""; for p in $(FUZZ_DEBS); do dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  echo "Installing Debian packages:$$missing"; \
	  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $$missing; \
	fi

fuzz-build: fuzz-deps
	CC=clang CXX=clang++ cmake -S . -B $(FUZZ_DIR) -G Ninja -DCMAKE_BUILD_TYPE=None \
	  -DCMAKE_CXX_FLAGS="$(SANITIZE_FLAGS) -g -O1 -fsanitize=fuzzer-no-link" \
	  -DMC_BUILD_FUZZ=ON -DMC_BUILD_TESTS=OFF -DMC_BUILD_PYTHON=OFF >/dev/null
	cmake --build $(FUZZ_DIR) -j $(JOBS) --target $(addprefix fuzz_,$(FUZZ_TARGETS))
	$(PYTHON) tests/fuzz/make_seeds.py $(FUZZ_DIR)/seeds

fuzz: fuzz-build
	@for t in $(FUZZ_TARGETS); do \
	  mkdir -p $(FUZZ_DIR)/corpus/$$t $(FUZZ_DIR)/findings/$$t; \
	  echo "fuzz_$$t: $(FUZZ_TIME) s"; \
	  $(FUZZ_DIR)/tests/fuzz/fuzz_$$t -max_total_time=$(FUZZ_TIME) -timeout=10 -rss_limit_mb=2048 \
	    -dict=tests/fuzz/$$t.dict -artifact_prefix=$(FUZZ_DIR)/findings/$$t/ -print_final_stats=1 \
	    $(FUZZ_DIR)/corpus/$$t $(FUZZ_DIR)/seeds/$$t 2>$(FUZZ_DIR)/fuzz_$$t.log \
	    || { tail -n 40 $(FUZZ_DIR)/fuzz_$$t.log; exit 1; }; \
	  grep -E '^(stat::number_of_executed_units|#[0-9]+ +DONE)' $(FUZZ_DIR)/fuzz_$$t.log; \
	done

# The C++ tests and the Python tests on a build with AddressSanitizer + UndefinedBehaviorSanitizer
# (issue 16), in build/sanitize (GCC; installed into build/sanitize/install, which the Python tests
# import first). -O0: the generated contact conditions take hours to compile with optimisation and
# the sanitizers on a shared 2-core machine. Python itself is not instrumented: libasan is preloaded, and its leaks (interned
# objects kept to the end) are not reported; the C++ tests check leaks too, except those allocated inside PETSc and
# OpenMPI (tests/sanitizers/lsan.supp).
SANITIZE_DIR := build/sanitize
SANITIZE_PYDIR := $(SANITIZE_DIR)/install/lib/python
SANITIZE_ENV := ASAN_OPTIONS=detect_leaks=0:abort_on_error=1:detect_odr_violation=0 \
                UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
                LD_PRELOAD="$$(g++ -print-file-name=libasan.so) $$(g++ -print-file-name=libubsan.so)" \
                PYTHONPATH=$(CURDIR)/$(SANITIZE_PYDIR)
sanitize-build: deps
	cmake -S . -B $(SANITIZE_DIR) -G Ninja -DCMAKE_BUILD_TYPE=None \
	  -DCMAKE_CXX_FLAGS="$(SANITIZE_FLAGS) -g1 -O0" -DMC_SANITIZED_BUILD=ON \
	  -DCMAKE_INSTALL_PREFIX=$(CURDIR)/$(SANITIZE_DIR)/install \
	  -DPython_EXECUTABLE=$$($(PYTHON) -c 'import sys; print(sys.executable)') \
	  -Dpybind11_DIR=$$($(PYTHON) -m pybind11 --cmakedir) >/dev/null
	cmake --build $(SANITIZE_DIR) -j $(JOBS)
	cmake --install $(SANITIZE_DIR) >/dev/null

test-sanitize: sanitize-build
	ASAN_OPTIONS=abort_on_error=1:detect_odr_violation=0 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	  LSAN_OPTIONS=suppressions=$(CURDIR)/tests/sanitizers/lsan.supp \
	  ctest --test-dir $(SANITIZE_DIR) --output-on-failure -j $(JOBS)
	$(SANITIZE_ENV) $(PYTHON) -m pytest -q -p no:cacheprovider tests/python

clean:
	rm -rf build
