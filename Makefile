# mortarcontact — one-command set-up, build, demo, tests and benchmarks (run as root on Debian).
PYTHON ?= python3
JOBS ?= $(shell nproc)
BUILD_DIR := build/cmake
DEBS := g++ cmake ninja-build ccache pkg-config libeigen3-dev libsuitesparse-dev libmetis-dev \
        nlohmann-json3-dev libnanoflann-dev libhdf5-dev libgtest-dev libmuparser-dev \
        libglu1-mesa libxcursor1 libxft2 libxinerama1 libopenblas0-openmp petsc-dev clang-format
PY_BUILD := scikit-build-core pybind11 ninja cmake
PY_RUN := numpy scipy meshio h5py rich pytest sympy matplotlib gmsh
# ruff pinned to a minor release: new minor releases stabilise new rules of the selected families.
PY_LINT := ruff~=0.17.6
CLANG_FORMAT ?= clang-format
# The hand-written C++ (.clang-format); the generated conditions are compared byte for byte with
# their generator's output instead.
CXX_FILES := git ls-files -z -- '*.h' '*.hpp' '*.cpp' '*.cc' ':(exclude)custom_conditions/generated/*' \
             ':(exclude)tests/cases/*' ':(exclude)build/*' ':(exclude,glob)**/.venv/**'

.PHONY: all deps install demo test lint format test-cpp test-python bench bench-large bench-robustness clean

all: install

deps:
	@missing=""; for p in $(DEBS); do dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  echo "Installing Debian packages:$$missing"; \
	  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $$missing; \
	fi
	@$(PYTHON) -m pip install -q --disable-pip-version-check $(PY_BUILD) $(PY_RUN) '$(PY_LINT)'

# Incremental: scikit-build-core reuses $(BUILD_DIR) and ccache caches objects.
install: deps
	CMAKE_BUILD_PARALLEL_LEVEL=$(JOBS) $(PYTHON) -m pip install -q --disable-pip-version-check \
	  --no-build-isolation --no-deps .

demo: install
	cd examples/hertz_cylinder && $(PYTHON) run_demo.py

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

# Structural block (0.1M-1M DoFs), Hertz cases and the structural parity sweep side by side with
# Kratos 10.4 (its wheels go into a separate virtual environment created by the scripts, never
# into this one).
bench: install
	$(PYTHON) benchmarks/run_benchmarks.py
	$(PYTHON) benchmarks/hertz/compare.py --cases hertz2d_2k,hertz2d_8k,hertz2d_30k,hertz3d_15k,hertz3dgrid_15k
	$(PYTHON) benchmarks/hertz/reuse_ab.py
	$(PYTHON) benchmarks/hertz/linear_solvers.py
	$(PYTHON) benchmarks/hertz/contact_scaling.py
	$(PYTHON) benchmarks/structural_parity/run.py

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

clean:
	rm -rf build
