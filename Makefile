# Two entry points a new user needs: `make demo` and `make test`.
# Both do the whole set-up first (apt packages when root, .venv, pip packages),
# and are no-ops for set-up when it is already done.

PYTHON ?= python3.11
VENV   := .venv
PY     := $(VENV)/bin/python
PIP    := $(PY) -m pip
STAMP  := $(VENV)/.installed
APT_PACKAGES := libusb-1.0-0 libgomp1 mona
PYTEST_FLAGS ?= -p no:dash -q

.PHONY: all setup apt venv demo test bench fuzz lint clean

all: test

setup: $(STAMP)

# System packages: open3d needs libusb, ltlf2dfa (the test oracle) needs mona.
apt:
	@if [ "$$(id -u)" = "0" ]; then \
	  missing=""; for p in $(APT_PACKAGES); do dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	  if [ -n "$$missing" ]; then \
	    echo "apt-get install:$$missing"; \
	    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $$missing >/dev/null; \
	  fi; \
	else \
	  for p in $(APT_PACKAGES); do dpkg -s $$p >/dev/null 2>&1 || echo "warning: not root, and Debian package $$p is missing: run 'sudo apt-get install -y $(APT_PACKAGES)'"; done; \
	fi

# torch==2.13.0 goes first and again in the same command as everything else, so that
# transformers / sentence-transformers never pull a CUDA build of torch.
$(STAMP): requirements.txt setup.py | apt
	@test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PIP) install -q --upgrade pip
	$(PIP) install -q torch==2.13.0
	$(PIP) install -q torch==2.13.0 -r requirements.txt
	$(PIP) install -q --no-deps --no-build-isolation -e .
	@touch $(STAMP)

venv: $(STAMP)

demo: apt $(STAMP)
	$(VENV)/bin/ltl-instruct demo

test: apt $(STAMP)
	$(PY) -m pytest $(PYTEST_FLAGS) test

bench: apt $(STAMP)
	$(PY) -m bench

# issue 21: hypothesis-generated inputs against every entry point (about 10 min), then
# 1,000 malformed messages among 100 valid instructions through the running graph
fuzz: apt $(STAMP)
	$(PY) -m bench.fuzz
	$(PY) -m bench.graph_fuzz

lint: $(STAMP)
	$(PY) -m flake8 ltl_instruct test bench
	$(PY) -m pydocstyle ltl_instruct

clean:
	rm -rf $(VENV) build *.egg-info .pytest_cache
