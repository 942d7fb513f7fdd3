"""Run every benchmark in ``bench/`` in turn (``make bench``); each prints its own figures."""
import importlib
import pkgutil
import sys
import time

import bench

FUZZERS = ('fuzz', 'graph_fuzz')   # make fuzz runs them (long, and they count breakages, not speed)


def main() -> int:
    """Run the main function of each bench module, or of those named on the command line."""
    names = sys.argv[1:] or sorted(m.name for m in pkgutil.iter_modules(bench.__path__)
                                   if not m.name.startswith('_') and m.name not in FUZZERS)
    failed = 0
    for name in names:
        print(f'=== bench.{name}', flush=True)
        t0 = time.perf_counter()
        try:
            rc = importlib.import_module(f'bench.{name}').main([])
        except SystemExit as e:  # a benchmark may exit with a status
            rc = e.code if isinstance(e.code, int) else 1
        failed += bool(rc)
        print(f'=== bench.{name}: {"ok" if not rc else "FAILED"} in {time.perf_counter() - t0:.1f} s\n')
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
