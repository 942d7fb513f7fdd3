"""The offline translator's lexicon: the words and phrases each kind of clause is read by.

Word lists for goals, deliveries, avoidances, staying within a region, order and noise
phrases, and the words at which clauses start. The clause reader
(:mod:`ltl_instruct.core.language.offline`) looks words up here; nothing here reads text.
"""
from __future__ import annotations

from typing import Sequence

from ltl_instruct.core.spec import Descriptor

AVOID_TRIGGERS: tuple[tuple[str, ...], ...] = tuple(sorted((
    ('avoid',), ('stay', 'away', 'from'), ('keep', 'away', 'from'), ('keep', 'off'), ('stay', 'off'),
    ('stay', 'clear', 'of'), ('steer', 'clear', 'of'), ('keep', 'clear', 'of'), ('stay', 'out', 'of'),
    ('keep', 'out', 'of'), ('do', 'not'), ('never',), ('not',), ('keep', 'your', 'distance', 'from'),
    ('stay', 'far', 'from'), ('keep', 'far', 'from'), ('stay', 'far', 'of'), ('keep', 'far', 'of'),
    ('without', 'going'), ('without', 'passing'),
    ('without', 'touching'), ('stay', 'away'), ('keep', 'away'), ('and', 'not'), ('but', 'not'),
    ('avoiding',), ('while', 'avoiding'), ('no',), ('shun',), ('always', 'avoid'), ('always', 'avoiding'),
    ('without',), ('always', 'stay', 'away', 'from'), ('go', 'anywhere', 'but'), ('go', 'anywhere', 'except'),
    ('anywhere', 'but'), ('anywhere', 'except'), ('go', 'anywhere', 'other', 'than'),
    ('while', 'staying', 'away', 'from'), ('keep', 'avoiding'), ('bypass',),
    ('keep', 'staying', 'away', 'from'),
    ('keep', 'away', 'from'), ('while', 'keeping', 'away', 'from'),
    ('staying', 'away', 'from'), ('keeping', 'away', 'from'), ('you', 'cannot'), ('you', 'can', 'not'),
    ('staying', 'clear', 'of'), ('keeping', 'clear', 'of'), ('steering', 'clear', 'of'),
    ('you', 'must', 'not'), ('you', 'should', 'not'), ('must', 'not'), ('cannot',), ('should', 'not'),
), key=lambda t: -len(t)))

# After "do not"/"never": verbs and particles to skip before the avoided noun phrase.
AVOID_FILLER = frozenset('''
go ever drive fly walk move come get pass bump touch run head enter step visit stop cross approach
land anywhere back near close to by into in over through past on onto around at the area of again
even going passing touching knock hit disturb wake anywhere let yourself be into enter visiting follow
entering navigate navigating reaching reach move moving travel traveling travelling stepping step
walking fly flying driving going ever allowed permitted to first foot use ride wander stray drift take
outside inside out outdoors indoors show turn up
'''.split()) - {'the'} | {'revisit', 'revisiting', 'reenter'}

# Gerunds and participles of movement, skipped between "until"/"after"/"before" and the place.
EVENT_WORDS = frozenset('''
reached visited arrived checked passed gone been going visiting reaching seen see got gotten made
landed surveyed at there enter entering entered navigating navigated moving moved traveling
travelling travelled heading headed arriving touching touched stepping stepped walking walked flying
flew driving drove getting coming came returning returned finding found observing observe observed
hitting hit after pass cross crossed crossing visit go enter reach get arrive passing going travelling
traveling moving done covered photographed filmed
'''.split())

GOAL_VERBS_SEED = frozenset({'go', 'do', 'make', 'let', 'come', 'get', 'stop'})

GOAL_VERBS = frozenset('''
go goes head visit navigate move drive fly walk run come return check find locate reach get stop
swing make proceed travel survey inspect do continue advance report going heading navigating moving
travelling traveling flying driving walking visiting reaching land charge stand hover approach enter
circle pass explore search look patrol wander roll arrive be need want please robot drone hey can
could would you i will just also then now first next lastly finally and so okay kindly go ahead end
up
'''.split())
GOAL_PARTICLES = frozenset('''
to over by at for on out back in into through past up down your way off around toward towards inside
there from onto me quickly straight directly
'''.split())
FILLERS = frozenset('''
sometime sometimes
please pls hey robot drone can could would you will just also then now first next lastly finally and
so okay kindly i need want like to be sure make remember also yes alright right well oh hmm um er
but eventually must have should ensure required that certainly definitely simply though although
maybe perhaps possibly
'''.split())
DELIVER_VERBS = frozenset({'bring', 'take', 'carry', 'move', 'deliver', 'return', 'put', 'place', 'leave',
                           'drop', 'set', 'toss', 'throw', 'stick', 'transport', 'bin', 'dump', 'hand',
                           'stash', 'store', 'push', 'relocate', 'chuck', 'haul', 'lug', 'ferry', 'cart',
                           'wheel', 'tow', 'recycle', 'run'})
PUT_VERBS = frozenset({'put', 'place', 'leave', 'drop', 'set', 'toss', 'throw', 'stick', 'stash', 'store',
                       'dump', 'chuck'})
PICK_VERBS = frozenset({'pick', 'grab', 'fetch', 'collect', 'get', 'retrieve', 'lift'})
TRASH = Descriptor('trash_can')
RECYCLING = Descriptor('recycling_bin')   # where "recycle the can" drops it

NOT_BEFORE_VERB = frozenset({'you', 'i', 'we', 'to', 'must', 'should', 'please', 'and', 'then', 'or', ',',
                             'can', 'will', 'would', 'could', 'not', 'also', 'just', 'first', 'never',
                             'always',
                             'finally', 'lastly', 'next', 'once', 'let', 'robot', 'drone', 'hey', 'sometime',
                             'eventually', 'but', 'so', 'afterwards', 'need', 'want', 'only', 'cannot',
                             'may', 'might', 'shall', 'do', 'does', 'did', 'allowed', 'able', 'have', 'has',
                             'had', 'ever', 'dont', 'permitted', 'supposed', 'required', 'free', 'ok', 'okay',
                             'good', 'instead', 'rather', 'ahead', 'directly', 'straight', 'immediately',
                             'single', 'any', 'every', 'each', 'no'}) | \
    GOAL_VERBS_SEED

# Words a patrol instruction may say besides its places ("keep going back and forth between a and b").
PATROL_WORDS = GOAL_VERBS | GOAL_PARTICLES | FILLERS | frozenset('''
do not never ever don and or between of a number times often all each every them these locations places
landmarks rooms must should have has to you are is being allowed with no limits limit any order around circle
circling loop looping cycle exploring explore patrol patrolling visiting going moving traveling travelling
flying driving walking stopping stop cease quit until told otherwise always keep continue on over again while
without make sure ensure can cannot an the arbitrary continuously endlessly finite forever forth frequent
frequently future indefinitely infinite infinitely least once perpetually point repeatedly specific time
visited prohibited in
'''.split())

# Words that may open a trigger of a rule ("whenever", "as soon as", "visiting a means...").
RULE_WORDS = frozenset({'whenever', 'time', 'anytime', 'if', 'soon', 'after', 'once', 'when', 'moment',
                        'before', 'means', 'later', 'future', 'afterwards', 'afterward', 'immediately'})

# Words after which a clause opener ("do not", "never", "you must") does not start a new clause.
RUN_ON_NOT_AFTER = frozenset({'and', 'or', 'but', 'then', 'that', 'so', 'if', 'when', 'because', 'where',
                              'which', 'who', 'what', 'why', 'how', 'as', 'the', 'a', 'an', 'to', 'of', 'for',
                              'until', 'before', 'after', 'while', 'unless', 'whenever'})

# Words of place names that a speller would take for slips ("porta potty" is no "portal"). Read by no
# name: every word set of this module is the speller's lexicon (offline.rules_speller).
NAME_WORDS = frozenset({'porta', 'potty', 'portaloo', 'loo', 'cubby', 'mudroom'})

STRONG_VERBS = frozenset({'go', 'visit', 'reach', 'head', 'navigate', 'travel', 'proceed', 'move'})

# Trailing phrases that add nothing to the task ("at all costs", "on your travels").
NOISE_TAILS: tuple[tuple[str, ...], ...] = tuple(sorted((
    ('at', 'all', 'costs'), ('on', 'your', 'travels'), ('the', 'order', 'is', 'not', 'important'),
    ('there', 'can', 'be', 'other', 'locations', 'in', 'between'), ('sometime',), ('at', 'some', 'point'),
    ('order', 'is', 'not', 'important'), ('in', 'any', 'order', 'required'), ('required',),
    ('the', 'order', 'does', 'not', 'matter'), ('in', 'no', 'particular', 'order'), ('eventually',),
    ('at', 'least', 'once'), ('at', 'any', 'time'), ('at', 'any', 'instant'), ('ever',),
    ('as', 'many', 'times', 'as', 'you', 'want'), ('as', 'many', 'times', 'as', 'you', 'like'),
    ('as', 'often', 'as', 'you', 'want'), ('as', 'often', 'as', 'you', 'like'), ('in', 'the', 'future'),
    ('during', 'the', 'round'), ('during', 'your', 'round'), ('on', 'your', 'round'),
    ('during', 'the', 'shift'),
    ('completely',), ('entirely',), ('altogether',), ('during', 'your', 'shift'),
    ('during', 'the', 'patrol'), ('on', 'this', 'run'), ('during', 'the', 'run'),
), key=lambda t: -len(t)))
ORDER_TAILS: tuple[tuple[str, ...], ...] = (
    ('consecutively',), ('one', 'after', 'another'), ('in', 'sequence'), ('sequentially',),
    ('in', 'the', 'given', 'order'), ('in', 'the', 'same', 'order'), ('in', 'this', 'order'),
    ('in', 'that', 'order'), ('in', 'order'), ('one', 'after', 'the', 'other'),
    ('in', 'the', 'order', 'given'),
)
# "in that strict order", "without visiting any out of turn": no goal may come before the one it follows.
STRICT_ORDER_TAILS: tuple[tuple[str, ...], ...] = tuple(sorted((
    ('in', 'that', 'specific', 'order'), ('in', 'this', 'strict', 'order'), ('in', 'that', 'strict', 'order'),
    ('in', 'this', 'specific', 'order'), ('in', 'strict', 'order'), ('in', 'strictly', 'this', 'order'),
    ('in', 'strictly', 'that', 'order'), ('strictly', 'in', 'this', 'order'),
    ('strictly', 'in', 'that', 'order'),
    ('strictly', 'in', 'order'), ('in', 'the', 'exact', 'order'), ('in', 'exactly', 'that', 'order'),
    ('in', 'exactly', 'this', 'order'), ('in', 'that', 'exact', 'order'), ('in', 'this', 'exact', 'order'),
    ('in', 'the', 'following', 'strict', 'order'), ('in', 'strict', 'sequence'),
    ('follow', 'this', 'strict', 'order'), ('in', 'this', 'exact', 'sequence'),
    ('in', 'that', 'exact', 'sequence'), ('in', 'that', 'exact', 'order'),
    ('make', 'sure', 'not', 'to', 'visit', 'waypoints', 'out', 'of', 'turn'),
    ('make', 'sure', 'not', 'to', 'visit', 'locations', 'out', 'of', 'turn'),
    ('ensure', 'to', 'not', 'visit', 'locations', 'out', 'of', 'turn'),
    ('ensure', 'to', 'not', 'visit', 'waypoints', 'out', 'of', 'turn'),
    ('without', 'visiting', 'any', 'out', 'of', 'turn'), ('never', 'out', 'of', 'turn'),
    ('not', 'out', 'of', 'turn'),
), key=lambda t: -len(t)))

IGNORED_CLAUSES = frozenset({
    # where to leave it, either place said: the choice is the robot's ("..., wherever")
    'wherever', 'wherever you like', 'wherever you want', 'wherever is easier', 'wherever is easiest',
    'wherever is closer', 'wherever is nearer', 'wherever is fine', 'wherever works',
    'whichever', 'i do not care which', 'order does not matter', 'whatever you do', 'take off', 'lift off',
    'launch',
    'the order does not matter', 'any order', 'in any order', 'whichever one', 'either one', 'thanks',
    'thank you', 'okay', 'in that order', 'in order', 'whichever is closer', 'it does not matter which',
    'either one works', 'either works', 'any works', 'either is fine', 'either one is fine', 'off you go',
    'away you go', 'go on', 'chop chop', 'your choice', 'up to you', 'i do not mind which',
    'does not matter which', 'does not matter',
    'does not matter which one', 'do not care which', 'do not care which one', 'your call', 'start',
    'start up', 'go ahead', 'stop', 'stop there',
    'and stop', 'then stop', 'stay there', 'stop moving', 'finish', 'be done', 'done', 'and be done',
    'first', 'second', 'third', 'fourth', 'fifth', 'secondly', 'thirdly', 'firstly', 'next', 'lastly',
    'finally', 'then', 'after that', 'afterwards', 'land', 'land there', 'and land', 'then land'})

# "stay on the third floor", "do not leave the red room": the robot stays within a region.
STAY_WITHIN: tuple[tuple[str, ...], ...] = tuple(sorted((
    ('cannot', 'leave'), ('must', 'not', 'leave'), ('not', 'leave'), ('should', 'not', 'leave'),
    ('stay', 'in'), ('stay', 'on'), ('stay', 'within'), ('stay', 'inside'), ('remain', 'in'),
    ('remain', 'on'), ('remain', 'within'), ('remain', 'inside'), ('do', 'not', 'leave'),
    ('never', 'leave'), ('do', 'not', 'exit'), ('do', 'not', 'navigate', 'away', 'from'),
    ('do', 'not', 'move', 'away', 'from'), ('never', 'move', 'outside', 'of'),
    ('never', 'go', 'outside', 'of'), ('do', 'not', 'go', 'outside', 'of'), ('without', 'leaving'),
    ('without', 'exiting'), ('only', 'stepping', 'in'), ('by', 'only', 'stepping', 'in'),
    ('always', 'stay', 'in'), ('always', 'stay', 'on'), ('always', 'remain', 'in'),
    ('always', 'remain', 'on'), ('never', 'exit'), ('do', 'not', 'step', 'out', 'of'),
    ('never', 'step', 'out', 'of'), ('stay', 'at'), ('remain', 'at'), ('do', 'not', 'leave', 'from'),
    ('you', 'cannot', 'leave'), ('you', 'can', 'not', 'leave'), ('you', 'must', 'not', 'leave'),
    ('keep', 'going', 'on'), ('wait', 'at'), ('wait', 'in'), ('stay', 'put', 'at'),
    ('are', 'not', 'allowed', 'to', 'leave'), ('do', 'not', 'move', 'outside', 'of'),
    ('only', 'walk', 'in'), ('while', 'staying', 'in'), ('while', 'staying', 'on'),
    ('while', 'remaining', 'in'), ('while', 'remaining', 'on'), ('staying', 'on'), ('staying', 'in'),
    ('staying', 'within'), ('remaining', 'on'), ('remaining', 'in'), ('remaining', 'within'),
    ('by', 'only', 'navigating', 'within'), ('by', 'only', 'navigating', 'in'),
    ('by', 'only', 'moving', 'in'), ('by', 'only', 'moving', 'within'), ('only', 'navigating', 'within'),
    ('only', 'moving', 'in'), ('without', 'stepping', 'outside', 'of'), ('without', 'stepping', 'outside'),
    ('without', 'ever', 'leaving'), ('without', 'stepping', 'out', 'of'), ('never', 'leaving'),
    ('only', 'through'), ('by', 'staying', 'in'), ('by', 'staying', 'on'), ('by', 'staying', 'within'),
), key=lambda t: -len(t)))

CLAUSE_STARTERS = (GOAL_VERBS | DELIVER_VERBS | PICK_VERBS | {
    'only', 'not', 'never', 'do', 'stay', 'keep', 'avoid', 'on', 'once', 'after', 'before', 'while',
    'if', 'either', 'also', 'just', 'first', 'but', 'when', 'until', 'whatever', 'finally', 'no', 'steer',
    'along', 'take', 'fly', 'survey', 'drive', 'land', 'stop', 'swing', 'make', 'patrol', 'charge', 'hover',
    'whichever', 'order', 'in', 'twice', 'three', 'exactly', 'at', 'and', 'then', 'eventually', 'sometime',
    'afterwards', 'afterward', 'later', 'ensure', 'though', 'although'}) - {
    'be', 'robot', 'drone', 'hey', 'okay', 'kindly', 'so', 'now', 'lastly', 'up', 'end', 'ahead', 'i',
    'you', 'can', 'could', 'would', 'will', 'need', 'want', 'please'} | {'i', 'you', 'please'}


def by_first_word(phrases: Sequence[tuple[str, ...]]) -> dict[str, tuple[tuple[str, ...], ...]]:
    """Index phrases by their first word, keeping their order (longest first where sorted so)."""
    out: dict[str, list[tuple[str, ...]]] = {}
    for p in phrases:
        out.setdefault(p[0], []).append(p)
    return {k: tuple(v) for k, v in out.items()}


AVOID_BY_FIRST_WORD = by_first_word(AVOID_TRIGGERS)
STAY_BY_FIRST_WORD = by_first_word(STAY_WITHIN)
# Every word at which _clauses may see a clause boundary.
CLAUSE_OPENING_WORDS = STRONG_VERBS | {
    'only', 'then', 'and', ',', 'after', 'finally', 'afterwards', 'afterward', 'lastly', 'once', 'when',
    'before', 'always', 'do', 'never', 'ensure', 'make', 'you', 'not', 'leave', 'but', 'so', 'while', 'or',
    ':', ';', 'just'}   # ":" as in "be careful: never...", "Rover: head to..."
