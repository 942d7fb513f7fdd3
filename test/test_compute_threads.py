"""Issue 22: a process limits the threads of its numeric libraries, loaded before or after."""
from __future__ import annotations

import json
import os
import subprocess
import sys

from ltl_instruct.core.compute_threads import ENV_VARS

PROBE = '''
import json, sys
import numpy
from ltl_instruct.core.compute_threads import limit_compute_threads
limit_compute_threads(int(sys.argv[1]))
import torch   # loaded after the limit
from threadpoolctl import threadpool_info
print(json.dumps({"pools": sorted({p["internal_api"]: p["num_threads"] for p in threadpool_info()}.items()),
                  "torch": torch.get_num_threads()}))
'''


def _probe(threads: int) -> dict:
    env = {k: v for k, v in os.environ.items() if k not in ENV_VARS}   # the libraries' own defaults
    out = subprocess.run([sys.executable, '-c', PROBE, str(threads)], capture_output=True, text=True,
                         timeout=120, check=True, env=env)
    return json.loads(out.stdout.strip().splitlines()[-1])


def test_one_thread_limits_blas_openmp_and_torch_loaded_later():
    got = _probe(1)
    assert got['pools'] and all(n == 1 for _, n in got['pools']), got
    assert got['torch'] == 1, got


def test_zero_leaves_the_libraries_defaults():
    got = _probe(0)
    cores = len(os.sched_getaffinity(0))
    if cores > 1:
        assert got['torch'] > 1 or any(n > 1 for _, n in got['pools']), got
