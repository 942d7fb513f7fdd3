"""Sub-commands of ``ltl-instruct`` (see ``ltl_instruct/cli.py``)."""
