"""How many threads the numeric libraries of one process may use (issue 22: a bounded tail).

BLAS (numpy, scipy), OpenMP (open3d, torch's CPU kernels) and torch's own pools each
start one thread per core by default. Five nodes on one small computer then run five
times the cores' worth of threads, and a camera frame that takes 20 ms alone waits for
the planner's and the translator's threads: the tail, not the median, grows. Each node
limits its own process (the ``compute_threads`` parameter every node declares).
"""
from __future__ import annotations

import os
import sys

ENV_VARS = ('OMP_NUM_THREADS', 'OPENBLAS_NUM_THREADS', 'MKL_NUM_THREADS')


def limit_compute_threads(threads: int) -> None:
    """Let BLAS, OpenMP and torch use at most ``threads`` threads in this process (0: leave their defaults).

    Libraries already loaded are limited now (threadpoolctl, ``torch.set_num_threads``);
    the environment variables limit those loaded later.
    """
    if threads <= 0:
        return
    for name in ENV_VARS:
        os.environ[name] = str(threads)
    from threadpoolctl import threadpool_limits
    threadpool_limits(limits=threads)
    torch = sys.modules.get('torch')
    if torch is not None:
        torch.set_num_threads(threads)
