"""Task formulas: AST, parser, printer and descriptors (``spec/formula.md``)."""
from ltl_instruct.core.spec.ast import (  # noqa: F401
    COMPARATORS, EVENT_SKILLS, FALSE, KEYWORDS, SKILLS, TRUE, Always, And, Atom, Const,
    Descriptor, Eventually, Formula, Iff, Implies, Next, Not, Or, Relation, Release, Until,
    WeakNext, WeakUntil, atoms_of, avoided_referents_of, conj, disj, formula_depth,
    iter_subformulas, near, neg, referents_of, rename_descriptors,
)
from ltl_instruct.core.spec.parser import (  # noqa: F401
    DEFAULT_LIMITS, ParseLimits, parse_descriptor, parse_formula,
)
from ltl_instruct.core.spec.printer import format_descriptor, format_formula  # noqa: F401
