# parse3d — set-up and checks. `make demo` and `make test` work on a fresh machine.
PY ?= python3
VENV := .venv
BIN := $(VENV)/bin
# Blender as a module (bpy needs numpy<2, so it has a venv of its own) for the export test
# that imports GLB and USD in Blender; that test skips where bpy cannot be installed.
BLENDER_VENV := .venv-blender
SYSTEM_PACKAGES := libegl1 libegl-mesa0 libgl1-mesa-dri libvulkan1
# The browser for the PAG designer's tests (Debian's build; never a downloaded one).
TEST_SYSTEM_PACKAGES := $(SYSTEM_PACKAGES) chromium

.PHONY: demo test lint system system-test _apt venv install-demo install-all blender bench gallery clean

# Prints how long the set-up and the demo took, and the venv's size.
demo:
	@start=$$(date +%s); \
	$(MAKE) --no-print-directory install-demo || exit $$?; \
	mid=$$(date +%s); \
	$(BIN)/parse3d demo --out out/demo || exit $$?; \
	end=$$(date +%s); \
	echo "make demo: $$((end - start)) s (install $$((mid - start)) s, demo $$((end - mid)) s);" \
	  "venv: $$(du -sh $(VENV) | cut -f1) in $(VENV) (the demo's packages only; make test adds the rest)"

test: install-all blender
	@# the Khronos glTF validator (npm) for the GLB export test; skipped where npm is missing
	@if command -v npm >/dev/null 2>&1; then cd tests/gltf_validator && npm ci --no-audit --no-fund --silent; fi
	$(BIN)/ruff check src tests benchmarks
	@if [ -x $(BLENDER_VENV)/bin/python ]; then export PARSE3D_BLENDER_PYTHON=$(CURDIR)/$(BLENDER_VENV)/bin/python; fi; \
	$(BIN)/python -m pytest -n 2 -q

# Blender as a module in its own venv; a machine without a bpy wheel for its Python goes on
# without it (the Blender export test then skips and says why).
blender:
	@[ -x $(BLENDER_VENV)/bin/python ] && $(BLENDER_VENV)/bin/python -c "import bpy" 2>/dev/null || { \
	  rm -rf $(BLENDER_VENV) && $(PY) -m venv $(BLENDER_VENV) && \
	  $(BLENDER_VENV)/bin/pip install -q "bpy>=4.2" || { rm -rf $(BLENDER_VENV); \
	  echo "bpy could not be installed: the Blender export test will skip"; }; }

lint: install-all
	$(BIN)/ruff check src tests benchmarks

# System libraries for headless rendering (Mesa EGL) and for SAPIEN (Vulkan loader).
system:
	@$(MAKE) --no-print-directory _apt PACKAGES="$(SYSTEM_PACKAGES)"

system-test:
	@$(MAKE) --no-print-directory _apt PACKAGES="$(TEST_SYSTEM_PACKAGES)"

_apt:
	@missing=""; for p in $(PACKAGES); do dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  echo "installing system packages:$$missing"; \
	  SUDO=""; [ "$$(id -u)" = 0 ] || SUDO=sudo; \
	  $$SUDO apt-get update -qq && DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq $$missing; \
	fi

$(BIN)/python:
	$(PY) -m venv $(VENV)
	$(BIN)/pip install -q --upgrade pip

venv: $(BIN)/python

# What the demo runs (solve, settle, contacts, preview: the `demo` extra), pinned. The other
# extras (exports to USD, datasets, Ray, the VLM and layout experiments, the designer) come
# with `make test`, or one at a time: pip install -e '.[export]' (README, "Install").
install-demo: system venv
	$(BIN)/pip install -q --prefer-binary -c constraints.txt -e ".[demo]"

# Everything (every extra and the test tools); torch is the CPU build pinned in constraints.txt.
install-all: system-test venv
	$(BIN)/pip install -q -c constraints.txt -e ".[all]"

bench: install-all
	$(BIN)/python benchmarks/run_all.py

gallery: install-demo
	$(BIN)/parse3d assets gallery --out docs/gallery.png

clean:
	rm -rf $(VENV) $(BLENDER_VENV) out .pytest_cache .ruff_cache
