"""``python -m ltl_instruct`` is the ``ltl-instruct`` command."""
import sys

from ltl_instruct.cli import main

sys.exit(main())
