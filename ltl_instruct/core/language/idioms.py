"""Idioms rewritten to the plain phrasing the clause reader knows, before it reads them.

People say the same task many ways: "the maximum number of times you can visit the
shed is two", "you are allowed at most two visits to the shed" and "visiting the shed
more than twice is prohibited" all mean "visit the shed at most twice". Rather than
teach every clause reader each variant, this module rewrites the variants of a
construction to one canonical phrasing, on each sentence's tokens joined by spaces,
with regular expressions. Each entry of :data:`RULES` is one construction, named by an
example of it; they apply in order.

The rewrites only replace wording with an equivalent wording: they never guess a
referent or drop a word that carries meaning, so what the reader then cannot place
still raises an error naming it. Every pattern is linear to match (no nested
repetition), so hostile input cannot make matching slow.
"""
from __future__ import annotations

import re
from typing import Callable, NamedTuple, Union

from ltl_instruct.core.language.phrases import PLACEHOLDER_ADJECTIVES, singular, with_article
from ltl_instruct.core.language.prefilter import admits, required_text
from ltl_instruct.core.language.text import NUMBER_WORDS, ORDINALS

_NUM = r'(?:one|two|three|four|five|six|seven|eight|nine|ten|\d+)'
_KIND = r'(?:separate |distinct |different |individual )?'
_UNIT = r'(?:times?|occasions?|instances?|visits?|passes)'
# a count: "once", "twice", "three times", "four separate occasions"
_COUNT = rf'(?:once|twice|thrice|{_NUM} {_KIND}{_UNIT})'
_ORD = '(?:' + '|'.join(ORDINALS) + ')'
# words that belong to the frame of a sentence, never to a noun phrase inside it
_FRAME = (r'then|but|you|is|are|be|once|twice|thrice|more|less|fewer|at|on|for|in|again|must|has|have|'
          r'should|needs|need|shall|will|can|cannot|may|get|gets|do|not|never|no|until|before|after|when|'
          r'while|if|unless|whenever|make|sure|ensure|that|to|go|visit|reach|avoid|only')
# (an acronym stays upper case: "the IT closet")
_W = rf'(?:(?!(?:and|or|{_FRAME})\b)[a-zA-Z0-9_]+)'
# a noun phrase ("the red room", "a"), and a list of them ("a, b and c"): one bounded repetition
# each, so that matching stays linear
_NP = rf'(?:{_W}(?: {_W}){{0,6}})'
_NPS = rf'(?:{_W}(?: (?:(?!(?:{_FRAME})\b)[a-zA-Z0-9_,]+)){{0,12}}?)'
# connectives that open an event ("until", "as soon as")
_WHEN = (r'until|till|before|after|once|when|whenever|if|unless|as soon as|every time|each time|any time|'
         r'anytime|only after|not until')
# the passive's auxiliaries: "is", "must be", "has to be", "gets"
_PASSIVE = (r'(?:(?:must|has to|have to|should|needs to|need to|is to|are to|shall|will|can) (?:always )?be|'
            r'are|is|gets?)')
# movement verbs, plain, in -ing and as participles ("visit", "visiting", "visited")
_GO = (r'(?:visit|go to|reach|enter|pass through|go through|move to|travel to|navigate to|get to|'
       r'make your way to|head to|find|come to|walk to|fly to|drive to)')
# a thing named by up to four words, and the words that place one thing by another
_THING = r'(?:[a-z0-9_]+ ){0,3}?[a-z0-9_]+'
# a word of a rule before a list ("avoid the hall, the den, then ..."): the list is no route
_RULE_BEFORE = re.compile(r'\b(?:avoid|away|clear|never|not|off|out|except|skip|without|until|before|after|'
                          r'either|or)\b')
# a name with a number and no article ("gallery 3")
_LABELLED = r'[a-z]+ \d+'
_WHERE = (r'(?:on top of|on|under|underneath|beneath|behind|in front of|next to|beside|by|near|left of|'
          r'right of|to the left of|to the right of|above|below|inside|between)')
# words that tell two things of one kind apart ("the east or the west stairs")
_SIDE = (r'(?:east|west|north|south|left|right|front|back|upper|lower|upstairs|downstairs|inner|outer|'
         r'near|far|main|side|top|bottom|middle|first|second|third|big|small|large|red|blue|green|yellow|'
         r'white|black|grey|gray|brown|old|new|kids|guest|master)')
_GOING = (r'(?:visiting|going to|reaching|entering|passing through|going through|moving to|traveling to|'
          r'travelling to|navigating to|getting to|heading to|finding|coming to|walking to|flying to)')
# "you can go ...": what the one who goes is allowed or told to do, and the verbs of going there
_ALLOWED = r'(?:you|we) (?:can|may|are allowed to|should|must)'
_GOAL_VERB = r'(?:go|head|visit|proceed|enter|fly|come|move|drive|walk|land|stop|swing|pop|check)'
_GONE = r'(?:visited|been to|gone to|reached|entered|passed through|gone through|found|arrived at)'
_BACK = rf'(?:{_GO}|revisit|come back to|return to|go back to)'
_FORBIDDEN = r'(?:prohibited|forbidden|not allowed|not permitted|banned)'
_STAY = r'(?:stay|remain|wait|hold (?:your )?position)'
_SEE = r'(?:visit|see|observe)'
_HAPPEN = r'(?:occur|happen|hold|appear)'

_ACTIVE = {'brought': 'bring', 'taken': 'take', 'carried': 'carry', 'moved': 'move', 'put': 'put',
           'delivered': 'deliver'}
_PLAIN_AUX = ('is', 'are', 'get', 'gets')
_PLACES = r'(?:landmarks?|locations?|places?|waypoints?|ones?|goals?|them|rooms?|spots?)'
# the canonical wording of "no goal visited twice", which the clause reader knows
_NO_REVISITS = ' , visit each place only once , '
_CLAUSE_END = r'(?= ,| then| and| finally| only|$)'

_ORDINAL_OF = {'one': 'first', 'two': 'second', 'three': 'third', 'four': 'fourth', 'five': 'fifth',
               '1': 'first', '2': 'second', '3': 'third', '4': 'fourth', '5': 'fifth'}
_SMALL = '(?:' + '|'.join(_ORDINAL_OF) + ')'

_PRESENT = {'dropped off': 'drop off', 'dropped': 'drop', 'delivered': 'deliver', 'left': 'leave',
            'brought': 'bring', 'took': 'take', 'placed': 'place'}

Replacement = Union[str, Callable[['re.Match[str]'], str]]


class Rule(NamedTuple):
    """One construction: an example of it, the pattern, and the canonical wording."""

    example: str
    pattern: str
    replacement: Replacement


def _number(word: str) -> int:
    if word.isdigit():
        return int(word)
    return ORDINALS.get(word) or NUMBER_WORDS.get(word, 1)


def _count_of(text: str) -> int:
    """Return the number a count phrase names ("twice" -> 2, "three separate times" -> 3)."""
    return _number(text.split()[0])


def _times(n: int) -> str:
    return {1: 'once', 2: 'twice'}.get(n, f'{n} times')


def _plain(gerund: str) -> str:
    """Return the plain form of a movement verb in -ing ("going to" -> "go to")."""
    first, _, rest = gerund.partition(' ')
    stem = {'visiting': 'visit', 'going': 'go', 'reaching': 'reach', 'entering': 'enter', 'passing': 'pass',
            'moving': 'move', 'traveling': 'travel', 'travelling': 'travel', 'navigating': 'navigate',
            'getting': 'get', 'heading': 'head', 'finding': 'find', 'coming': 'come', 'walking': 'walk',
            'flying': 'fly', 'approaching': 'approach', 'crossing': 'cross', 'touching': 'touch',
            'using': 'use', 'leaving': 'leave', 'stopping': 'stop', 'driving': 'drive'}.get(first, first)
    return f'{stem} {rest}'.strip()


# When in the day a visit falls ("in the morning", "at night", "before lunch"): no place, no order.
_DAYTIME = (r'(?:(?:in the|at|this|before|after|during the|around|by|on|at about) )?(?:early |late )?'
            r'(?:morning|afternoon|evening|night|noon|midday|lunch|lunchtime|dinner|dinnertime|breakfast|'
            r'tea|teatime|supper|bedtime|bed|midnight|dawn|dusk|today|tonight|tomorrow|monday|tuesday|'
            r'wednesday|thursday|friday|saturday|sunday)')


def _spread(m: 're.Match[str]') -> str:
    # "twice, once in the morning and once at night": as many onces as the count, so it says the count again
    return m.group('c') if m.group('s').split().count('once') == _count_of(m.group('c')) else m.group(0)


def _group(m: 're.Match[str]', name: str) -> str:
    return m.group(name) or ''


def _upto(m: 're.Match[str]') -> str:
    # "zero times, once or twice": the largest count named is the bound
    counts = re.findall(rf'(?:once|twice|thrice|{_NUM} times?)', m.group(0))
    return f'at most {_times(max(_count_of(c) for c in counts))}'


# The bound a limit word names ("max", "minimum", "exactly"); any other ("no more than", "only") is "at most".
_BOUNDS = {'maximum': 'at most', 'max': 'at most', 'minimum': 'at least', 'min': 'at least',
           'at least': 'at least', 'required': 'exactly', 'exact': 'exactly', 'exactly': 'exactly'}


def _bound(m: 're.Match[str]') -> str:
    """Say a count with its bound: 'the maximum number of visits to X is three', 'max one visit to X'."""
    mode = _BOUNDS.get(m.group('bound'), 'at most')
    return f'visit {m.group("x")} {mode} {_times(_number(m.group("n").split()[-1]))}'


def _visits(m: 're.Match[str]') -> str:
    mode = _group(m, 'mode').strip().replace('only', 'exactly') or ('exactly' if m.group('only') else '')
    n = 1 if m.group('n') in ('a', 'an', 'single', 'any single') else _number(m.group('n'))
    return f'visit {m.group("x")} {mode + " " if mode else ""}{_times(n)}'


def _locks(m: 're.Match[str]') -> str:
    return f'visit {m.group("x")} at most {_times(_number(m.group("n")))}'


def _wait(m: 're.Match[str]') -> str:
    # "hold position at a as long as b does not happen": a until b
    return f'stay at {m.group("y")} until you visit {m.group("x1") or m.group("x2")}'


def _held(m: 're.Match[str]') -> str:
    # "once it is off your hands": it; "once you have let go of them": them
    if m.group('o'):
        return 'it' if m.group('o') == 'it' else 'them'
    return m.group('p')


# What a drone flies as a route, not as a load ("fly the perimeter to the gate", "fly the drone to X").
_FLOWN = frozenset('''
drone robot uav quad quadcopter copter aircraft route loop path perimeter circuit stretch leg lap laps fence
line boundary edge way course rest length corridor road river track pattern
'''.split())


def _carried(m: 're.Match[str]') -> str:
    """'fly the sensor to the mast' carries the sensor there; 'fly the perimeter to the gate' does not."""
    if m.group(0).startswith('fly') and m.group('x').split()[-1] in _FLOWN:
        return m.group(0)
    return f'carry {m.group("x")} {m.group("p")}'


def _each_named(m: 're.Match[str]') -> str:
    """Name one of each: 'the first and third floors' is 'the first floor and the third floor'."""
    words = m.group('n').split()
    if m.group('j') == 'and':
        words[-1] = singular(words[-1])
    n = ' '.join(words)
    return f'the {m.group("a")} {n} {m.group("j")} the {m.group("b")} {n}'


_LIST_THEN = (r'(?P<l>(?:the|my|your|our) [a-z0-9_]+(?: [a-z0-9_]+){0,3}?(?: , (?:the|my|your|our) '
              r'[a-z0-9_]+(?: [a-z0-9_]+){0,3}?){1,5})(?: ,)? and (?P<w>finally|lastly|last of all|at last) '
              r'(?=(?:the|my|your|our|to|go|come|head|return|back)\b)')


def _in_turn(m: 're.Match[str]') -> str:
    """Put each after the one before: 'the bench, the shelf, the lamp and finally the exit'."""
    return m.group('l').replace(' , ', ' , then ') + f' , and {m.group("w")} '


_LIST_COMMA_RE = re.compile(r' , (?:and )?(?:then )?')


def _in_order(places: str) -> str:
    """Join the places of a route with "then": 'crane 1 , crane 2 , and site office' -> '... then ...'."""
    return _LIST_COMMA_RE.sub(' then ', places)


def _put_or_move(m: 're.Match[str]') -> str:
    """Say where a thing goes as a delivery: "put" it in or on a place, "move" it to one."""
    return f'{"move" if m.group("p") == "to" else "put"} {m.group("x")} {m.group("p")}'


def _repeat(m: 're.Match[str]') -> str:
    mode = _group(m, 'mode').strip() or 'at least'
    return f'visit {m.group("x")} {mode} {_times(1 + _number(m.group("n")))}'


def _named_first(m: 're.Match[str]') -> str:
    """Put the one named first: 'the seat and the chair, the chair first' is the chair, then the seat."""
    a, b, c = m.group('a'), m.group('b'), m.group('c').split()
    words_a, words_b = a.split()[1:], b.split()[1:]
    if c == words_b[-len(c):] and c != words_a[-len(c):]:
        a, b = b, a
    elif not (c == words_a[-len(c):] and c != words_b[-len(c):]):
        return m.group(0)
    return f'{m.group("v")} {a} , then {b}'


def _comes_last(m: 're.Match[str]') -> str:
    """Say "the pond comes last: don't go to it until ..." as "... the pond until ..., and go to it last"."""
    rest = re.sub(r'\b(to|near|in|into|at) it\b', lambda k: f'{k.group(1)} {m.group("x")}', m.group('r'))
    return f'{rest} , and go to {m.group("x")} {m.group("w")}'


def _same_head(m: 're.Match[str]') -> str:
    """Name "one" by the noun it stands for: "the second floor ice machine or the third floor one".

    The new modifier replaces as many words at the front of the first name as it has.
    """
    first, other = m.group('x').split(), m.group('y').split()
    k = 0
    while k < len(first) - 1 and first[k] in PLACEHOLDER_ADJECTIVES and first[k] not in ORDINALS:
        k += 1   # "the big red box or the small one": a small box
    head = first[k:] if k else first[len(other):] if len(first) > len(other) else first[-1:]
    return f'the {m.group("x")} {m.group("j")} the {" ".join(other + head)}'


RULES: tuple[Rule, ...] = (
    # ---- "one" named by the noun it stands for
    Rule('the upstairs autoclave or the basement one',
         rf'\bthe (?P<x>{_W}(?: {_W}){{1,4}}) (?P<j>or|and) the (?P<y>{_W}(?: {_W}){{0,2}})'
         rf' one\b(?! (?:times?|more|single)\b)', _same_head),   # "the hall one time" is a count
    # ---- a place that needs the robot, a visit said another way
    Rule('room 204 needs you',
         rf'^(?P<x>(?:the )?{_NP}) (?:needs|need|wants|could use) (?:you|a body|the robot|'
         r'a hand|some help)(?: over there| there| here)?(?: and you are it)?\b(?! (?:at|in|by|on|near|over'
         r'|down|up|'
         r'out|inside|outside)\b)', r'go to \g<x>'),
    Rule('check with the security office', r'\b(?:check|checking|checked) (?:in )?with (?=the |my |our )',
         'visit '),
    Rule('not before signing in at the desk',
         r'\bsign(?P<g>ing|ed)? (?:in|out) (?:at|with) (?=the |my |our )',
         lambda m: {'ing': 'visiting ', 'ed': 'visited '}.get(m.group('g') or '', 'visit ')),
    Rule('keep her company by the bird bath',
         r'\bkeep (?:her|him|them|me|us|mum|mom|dad|grandma|grandpa|the [a-z]+) company (?=by|at|in|near|on)',
         'go '),
    Rule('check the front door one more time',
         r'\b(?<!exactly )(?<!least )(?<!most )(?:one more time|once more)\b', 'again'),
    Rule('then do that exact same trip again',
         r'\bdo (?:that|the|this) (?:exact |very )?same (?:trip|walk|route|loop|run|flight|circuit|round'
         r'|thing|'
         r'journey|leg)(?: over)?(?: again)?\b', 'do it again'),
    Rule('take the plates through to the dishwasher', r'\b(?:through|round|across) to\b', 'to'),
    Rule('after you have got rid of it', r'\b(?:have|you) (?:got|gotten) rid of\b', 'have dropped off'),
    Rule('once the laundry room and the linen cart are both done',
         rf'\b(?P<w>once|after) (?P<x>(?:the|my|our) {_NPS} and (?:the|my|our) {_NPS}) (?:are|have been) '
         r'(?:both |all )?(?:done|visited|checked|finished|complete|completed|sorted|covered)\b',
         r'\g<w> you have visited \g<x>'),
    Rule('go there once you have visited a and b, not earlier',
         r'\b(?<!only )(?P<w>once|after) (?P<x>[^,.;!?]{3,80}?) , not (?:earlier|before|sooner|until then)\b',
         r'only \g<w> \g<x>'),
    Rule('while the roast is in, check the oven',
         r'^while (?:the|my|your|our) (?:[a-z]+ ){1,3}?(?:is|are) (?:in|on|cooking|baking|running|drying'
         r'|charging|'
         r'asleep|sleeping|out|in the oven) , ', ''),
    Rule('from the moment you get there', r'\bfrom the moment (?:you|it) (?=get|reach|arrive|are|have)',
         'once you '),
    Rule('the sink becomes off limits',
         r'\b(?:becomes|will be|goes) (?=off limits|out of bounds|forbidden|a no go)',
         'is '),
    Rule('after they are in, keep away',
         r'\b(?P<c>once|after|when) (?P<o>it is|they are|it has been|they have been) (?:in|inside|in there'
         r'|down|in place|'
         r'dropped off|delivered|put away)(?= ,)',
         lambda m: f'{m.group("c")} you have dropped off ' + (
             'it' if m.group('o').startswith('it') else 'them')),
    Rule('until you are at the mail slot the copier is off limits',
         rf'^(?P<u>until|till) (?P<e>you (?:are|have been|reach|get to|have reached|have visited|arrive at'
         rf'|get)'
         rf'(?: at| in| to)? (?:the|my|our) {_W}(?: {_W}){{0,3}}?) (?:, )?(?P<x>the {_W}(?: {_W}){{0,3}})'
         rf' (?:is|are) '
         r'(?:off limits|out of bounds|forbidden|a no go)\b', r'avoid \g<x> \g<u> \g<e>'),
    Rule('avoid the trash can as you go',
         r'(?<!soon )\bas you (?:go|head there|make your way|travel)\b'
         r'(?! (?:to|into|towards|there|back|by|past|near|over|through|in|up|down|around)\b)', 'on the way'),
    Rule('leftovers go in the fridge',
         rf'^(?P<x>(?:the |some |my |your |our )?(?!(?:take|bring|put|please|first|without|just|now|so|also'
         rf'|let|'
         rf'make|get|fly|drive|head|walk)\b){_W}(?: {_W}){{0,3}}) (?:go|goes|belong|belongs|need to go|needs'
         rf' to go) '
         rf'(?P<p>in|into|on|back in|back on|back to|back into) (?P<y>(?:the|my|our) {_NP})$',
         lambda m: f'put {with_article(m.group("x"))} {m.group("p")} {m.group("y")}'),
    Rule('before you go anywhere near the vault you need the spare keycard: not until it is picked up',
         r'^(?:but |and |so )?before you (?:go|get|head) (?:anywhere )?(?:near|into|in|to) '
         r'(?P<x>(?:the|my|our) [^,.;!?]+?) (?:,? )?you (?:need|will need|must have|need to have|'
         r'have to have|'
         r'need to get|must get|have to get|should get) (?P<y>(?:the|my|our|a|an) [^,.;!?]+?)'
         r'(?: , (?:so )?(?:pick|grab|get|collect|fetch) (?:it|them) up)?(?= [,.;!?]|$)',
         r'do not go near \g<x> until you have picked up \g<y>'),
    Rule('I want you up at the grain store, but ...: go there',
         r'^(?:i|we) (?:want|need|would like) you (?:up |down |over |out |back )?(?:at|in|by) '
         r'(?=(?:the|my|our) [^,.;!?]* , (?:but |and )?(?:stop|call|pop|drop|swing|visit|check|look) )',
         'go to '),
    Rule('go to the front gate, but call in at reception on the way',
         rf'^(?P<a>(?:go|head|drive|fly|walk|get) (?:over |down |up )?to (?:the |my |our )?{_NP}) , (?:but '
         rf'|and )?'
         r'(?:visit|stop by|stop at|stop in at|stop off at|call in at|call at|call by|pop into|pop in at|'
         r'pop by|drop by|drop in at|swing by|check|look in at) '
         rf'(?P<y>(?:the |my |our )?{_NP}) (?:on the way|on your way|en route|along the way)(?: there)?$',
         r'visit \g<y> , then \g<a>'),
    Rule('no overflight of the highway: do not fly over it',
         r'\b(?:no|avoid|avoid any|avoid all) (?:overflights?|flyovers?|flying over) (?:of|over|above) ',
         'never fly over '),
    Rule('loop from the receiving dock to the shipping dock',
         r'\b(?:loop|do (?:the|a) (?:loop|run|walk|trip|circuit)|fly (?:the|a) (?:stretch|leg|route|loop))'
         r' from ',
         'go from '),
    Rule('kindly dispose of the used gloves', r'\b(?:dispose|get rid) of\b', 'throw away'),
    Rule('both the key and the card need to go to the front desk',
         rf'^(?:both )?(?P<x>(?:the|my|our) {_NP} and (?:the|my|our) {_NP}) (?:both )?(?:need|have) to go '
         rf'(?P<p>to|in|into|on) (?P<y>(?:the|my|our|room) {_NP})', r'bring \g<x> \g<p> \g<y>'),
    Rule('table 17 has a toddler, bring them a high chair: the thing, then to whom',
         rf'\b(?P<v>bring|take|get|fetch|grab) (?P<p>them|him|her) (?P<x>(?:a|an|the|some|another) {_THING}'
         rf'(?: (?:or|and) (?:a|an|the|some|another) {_THING})?)(?= [,.;!?]|$)', r'\g<v> \g<x> to \g<p>'),
    Rule('take the drone up and check on the pond',
         r'^(?:take|get|send|put) the (?:drone|quadcopter|copter) (?:up|out|airborne|into the air)'
         r'(?: and| ,)? ', ''),
    Rule('take your break in the staff room',
         r'\b(?:take|have) (?:your|a) (?:break|rest|lunch|breather|nap|coffee break) (?:in|at) ',
         'go to '),
    Rule('and finish up at dock two', r'\b(?:finish|end|wind) up (?:at|in|by) ', 'go to '),
    Rule('stay out of the way of the stairwell door',
         r'\b(?P<v>stay|keep) out of the way of\b', r'\g<v> away from'),
    Rule('keep out of the calf shed until you have been to the wash bay, then go on in',
         r'(?:(?<=\bthen )|(?<=\band ))(?:go|head|walk|move) (?:on )?(?:in|inside|in there)(?= [,.;!?]|$)',
         'go to it'),
    Rule('go stand right next to it',
         r'\bright (?=next to|behind|in front of|beside|by|under|outside|inside)', ''),
    Rule('only head to the garage once the dock is done',
         rf'\b(?P<w>once|after) (?P<x>(?:the|my|our) {_NP}) (?:is|has been) (?:done|checked|finished'
         rf'|complete|'
         r'completed|sorted|covered|dealt with)\b', r'\g<w> you have visited \g<x>'),
    Rule('do not set foot in there without it',
         r'\b(?P<n>do not|never) (?:set foot in|go in|go into|enter|go to) (?P<x>there|it|the [a-z_ ]+?)'
         r' without '
         r'(?:it|them)\b', r'\g<n> go to \g<x> until you have picked it up'),
    Rule('throw away that broken glass',
         r'\b(?P<v>throw away|throw out|bin|toss|bring|take|grab|fetch|put|move|carry|pick up|go to|visit) '
         r'that(?= [a-z])(?! (?:is|was|one|ones|way|much|far)\b)', r'\g<v> the'),
    Rule('do not you go near', r'\bdo not you\b', 'do not'),
    Rule('you can call in at the office if you need to, but once at most',
         r'\byou (?:can|may|could) (?:stop by|call in at|call at|visit|pop into|drop by|go to|stop at|swing'
         r' by) '
         rf'(?P<x>the {_W}(?: {_W}){{0,4}}?)(?: too| as well)?(?: on the way)?(?: if you (?:want|need to'
         rf'|like|must|have to|wish))?'
         r' , but '
         r'(?:only )?once(?: at (?:the )?(?:very )?most)?\b', r'visit \g<x> at most once'),
    Rule('table 12 or 14',
         r'\b(?P<n>table|room|bay|bed|dock|aisle|gate|door|stall|pen|paddock|booth|desk|platform) '
         r'(?P<a>\d+|one|two|three|four|five|six|seven|eight|nine|ten) (?P<j>or|and) '
         r'(?P<b>\d+|one|two|three|four|five|six|seven|eight|nine|ten)\b(?! (?:times|of)\b)',
         r'\g<n> \g<a> \g<j> \g<n> \g<b>'),
    Rule('you have got the bakery counter, the deli and the checkout to visit: visit them',
         r'^(?:you have|you|we have|we|there is|there are) (?:got )?(?P<x>(?:the|my|your|our) [^.;]+?) '
         r'to (?:visit|check|see|inspect|get to|hit|cover|stop at|go to)(?: today| now| this morning)?$',
         r'visit \g<x>'),
    Rule('the checkout comes last, after both of the others: last',
         rf'^(?P<x>(?:the|my|your|our) {_THING}) (?:comes|goes|is) last(?: ,)? after (?:both|all|each) '
         rf'(?:of )?(?:the|my|your|our) [a-z0-9_ ]+$', r'\g<x> is last'),
    Rule('the bar comes last: do the ice machine and the glass rack first',
         rf'^(?P<x>(?:the|my|our) {_NP}) (?:comes|goes|is|should be|has to be|must be) (?P<w>last|first) '
         r'(?:,|:) (?P<r>.+)$', _comes_last),
    Rule('route around the loading ramp: keep away from it',
         r'\b(?:route|detour|navigate|drive|steer|work your way|find a way|path) (?:around|round) '
         r'(?=(?:the|my|your|our|any) )', 'avoid '),
    Rule('no entry to the hazmat cage: no going into it',
         r'\bno (?:entry|access|entering|admittance) (?:to|into|in|inside) (?=(?:the|my|your|our|any) )',
         'no going into '),
    Rule('visit the den and the hall, the order matters: in this order',
         r'(?:, )?\b(?:and )?(?:the |that |this )?order (?:matters|is important|counts|is key)'
         r'(?: to (?:me|us))?\b(?! (?:not|less|little))',
         ', in this order'),
    Rule('go via the main lifts down to pharmacy',
         rf'\b(?P<v>go|head|come|drive|fly|walk|travel) via (?P<x>(?:the|my|our) {_NP}) (?:down |up |over '
         rf'|across |on )?'
         r'to\b', r'\g<v> to \g<x> , then to'),
    # "go to the kitchen, passing through the hall": the hall is on the way, not a later goal
    # (clean-up's validation split had it after the goal; the rules made the hall a second goal and
    # `near[passing]` a third)
    Rule('go to the blue room and make sure to go through the green room: via the green room',
         r'(?: ,| and) (?:make sure (?:to|you) |be sure to |remember to )?(?:pass|passing|go|going|travel|'
         r'travelling|traveling|walk|walking|drive|driving|move|moving|cut|cutting) through '
         r'(?=(?:the|my|our|a|an) )',
         ' via '),
    # "the closest chair to the door" is "the chair closest to the door" (a relation, not a name)
    Rule('the closest chair to the door: the chair closest to the door',
         rf'\b(?P<d>the|a) (?P<s>closest|nearest) (?P<x>{_W}(?: {_W}){{0,2}}) to '
         r'(?=(?:the|my|our|your|a|an) )',
         r'\g<d> \g<x> \g<s> to '),
    Rule('take the stairs or the lift',
         r'\btake (?P<e>either )?(?=the (?:[a-z]+ )?(?:lift|lifts|stairs|elevator|elevators|escalator'
         r'|stairwell|ramp|'
         r'footbridge|bridge|path|corridor|route|road|exit|back stairs|fire escape)\b)', r'go to \g<e>'),
    Rule('should you need to enter the garage at any point, go by the door beforehand',
         rf'^should you (?:need|want|have|wish) to (?P<v>enter|visit|go to|go into|use) (?P<x>(?:the|my|our)'
         rf' {_NP})'
         r'(?: at any point| at all| at any time)? , (?P<r>[^,;!?]+?) (?:beforehand|first|before that|before'
         r' you do)$',
         r'if you \g<v> \g<x> at all , \g<r> first'),
    Rule('making only one trip to the sink',
         rf'\b(?:making|make|with) (?:only |just )?(?:one|a single) (?:trip|visit|run|stop) (?:to|into|at) '
         rf'(?P<x>the {_NP})', r'visit \g<x> at most once'),
    Rule('the meeting room needs the stapler and the tape, bring them both in',
         rf'^(?P<x>the {_NP}) (?:needs|need|wants) (?P<y>(?:the|a|an|some) {_NPS}) , (?:please )?(?:bring'
         rf'|take|carry) '
         r'(?:them|it)(?: both| all| over)? (?:in|there|over|along)\b', r'bring \g<y> to \g<x>'),
    Rule('the first two belong in the drawer, put them away',
         rf'(?P<x>the {_NPS})(?: both| all)? (?:belong|belongs|go|goes) (?P<p>in|on|into|back in|back on|'
         rf'back into) (?P<y>the {_NP}) [,;.] (?:please )?(?:put|take|bring) (?:them|it|the [^,.;!?]+?) '
         r'(?:away|there|back|over)\b',
         r'put \g<x> \g<p> \g<y>'),
    Rule('some boxes got stacked behind the desk, go to them',
         rf'^(?:some |the |a |an |my |her |his |their |our |your )?(?P<x>{_W}(?: {_W}){{0,3}}?) (?:that )?'
         r'(?:i need |i want |i mean )?(?:is|are|was|'
         r'were|got|have been|has been)(?: (?:stacked|left|put|placed|sitting|lying|dumped|piled|parked'
         r'|kept))? '
         r'(?P<y>(?:behind|under|on|next to|beside|by|in front of|between|on top of|underneath|beneath|left'
         r' of|'
         r'right of|to the left of|to the right of|inside|near) [^,]+?) , (?:(?:go|head|get|move|navigate)'
         r' (?:over )?to|'
         r'(?:go |go and )?find) (?:it|them|that|those)\b', r'go to the \g<x> \g<y>'),
    Rule('still avoiding the printer on the way',
         r' , (?:still |while |all the while |but )?(?:avoiding|skirting) ',
         ' , and avoid '),
    Rule('keep the front desk out of your flight path',
         rf'\bkeep (?P<x>the {_NP}) out of (?:your|the) (?:flight )?(?:path|way|route)\b', r'avoid \g<x>'),
    Rule('fly through the break room and out to the lot', r'\band (?:out|over|down|up|across) to\b',
         'and then to'),
    # ---- formal words for plain ones
    Rule('refrain from approaching the freezer',
         r'\b(?:kindly |please )?refrain from (?:ever )?(?P<v>[a-z]+ing)\b',
         lambda m: f'do not {_plain(m.group("v"))}'),
    Rule('and subsequently the centrifuge', r'\bsubsequently\b', 'then'),
    # ---- connectives that add a clause or offer another (read as names before: "near[furthermore]")
    Rule('go to the den ; moreover , never enter the hall: and (nothing at the start of a sentence)',
         r'(?:^|(?<=, )|(?<=; ))(?:moreover|furthermore|additionally|in addition(?! to\b)|'
         r'(?:in addition to|on top of|besides) (?:that|this)|what is more|plus|over and above that)(?: ,)? ',
         lambda m: '' if m.start() == 0 else 'and '),
    Rule('go to the kitchen , otherwise go to the garage: or',
         r'(?:^|(?<=, ))(?:otherwise|alternatively|failing that|if not)(?: ,)? '
         r'(?=(?:just )?(?:go|head|visit|move|drive|fly|walk|come|proceed|travel|take|bring|deliver|try)\b)',
         'or '),
    Rule('the shower prior to the hood', r'\bprior to\b', 'before'),
    # ---- modal frames said at length: permission, obligation, prohibition
    Rule('you are not allowed to go there',
         r'\byou are (?:not|never) (?:allowed|permitted) to\b', 'you cannot'),
    Rule('you are allowed at most two visits',
         rf'\byou are (?P<neg>not )?(?:allowed|permitted) (?=(?:at least|at most|exactly|only|no more than|'
         rf'{_NUM}|once|twice) )',
         lambda m: 'you cannot make ' if m.group('neg') else 'you can make '),
    Rule('you are allowed to go there', r'\byou are (?:allowed|permitted|good|free|able) to\b', 'you can'),
    Rule('your task is to go there',
         r'\b(?:you are required to|your task is to|your job is to|your goal is to|you are supposed to|'
         r'you are expected to)\b', 'you must'),
    # "but if you go to side room 2 go to the PPE station first": spoken, the condition ends at the
    # command's verb
    Rule('if you go to side room 2 go to the station first',
         rf'\b(?P<c>(?:if|should|when|in case) you (?:go to|go into|go in|visit|choose|pick|enter|end up at|'
         rf'end up in|decide on|opt for) (?:the |my |your |our )?{_W}(?: {_W}){{0,4}}?) '
         r'(?=(?:go|head|visit|stop|check|keep|stay|avoid|do not|never|you must|you have to|make sure|swing|'
         r'pop)\b)',
         r'\g<c> , '),
    # "the sluice room or the dirty utility only one of them though not both": but not both
    Rule('only one of them though not both',
         r'(?:, )?\b(?:but )?(?:only |just )?one of (?:them|the two)(?: ,)?(?: though| mind| please)?(?: ,)? '
         r'(?:but )?not both\b',
         ' but not both'),
    # "go to the freezer room, and from there continue to bench 4": then to it
    Rule('and from there continue to bench 4',
         r'(?:, )?(?:and )?from there(?: ,)? (?:continue|carry on|proceed|go|head|move|fly|go on|move on)'
         r'(?: on| onward| onwards)? (?=to )',
         ' , then go '),
    # "bring only the latter to the fume hood": the one thing delivered, no rule of its own
    Rule('bring only the flask to the hood',
         r'\b(?P<v>bring|take|carry|move|put|deliver|return) (?:only|just) (?=(?:the|my|your|our|a|an) )',
         r'\g<v> '),
    # formal orders: "You are not to go near X until ...", "you are to approach X exactly once", with an
    # aside between ("You are not, however, to collect it before ...")
    Rule('you are not, however, to collect it',
         r'\b(?:you are not|you must not|you cannot|do not) , (?:(?:however|though|of course|therefore|'
         r'also|in any case|at any point) , )?(?:to )?(?=[a-z])', 'do not '),
    Rule('you are not to go near X', r'\byou are not to\b', 'do not'),
    Rule('you cannot finish the task without visiting X',
         rf'\b(?:you cannot|you can not|you must not|do not) (?:complete|finish|end) '
         rf'(?:the task |the mission |your task )?without (?P<verb>{_GOING})\b',
         lambda m: _plain(m.group('verb'))),

    # ---- events said at length: "the moment you've got hold of it", "once it's off your hands"
    Rule('as soon as you have picked it up',
         r'(?:^|(?<=, )|(?<=\band )|(?<=\bbut ))(?:as soon as|the moment|the minute|the second|the instant)'
         r'(?= you (?:have )?(?:[a-z]+ ){1,3}(?:it|them)\b| (?:it|they) (?:is|are) )', 'once'),
    Rule('once you have got hold of it',
         r'\b(?P<c>once|when|after|until|before) you (?:have |ve )?(?:got|gotten|get|grabbed|taken|take) '
         r'hold of '
         r'(?P<o>it|them)\b', r'\g<c> you have picked \g<o> up'),
    Rule('once it is off your hands',
         r'\b(?P<c>once|when|after) (?:(?P<o>it|they) (?:is|are) off your hands|you (?:have )?(?:let go of|'
         r'set down|put down|handed over|parted with) (?P<p>it|them))\b',
         lambda m: f'{m.group("c")} you drop {_held(m)} off'),
    Rule('pick up the cup and fly it over to the sink: moving what is held is carrying it',
         r'(?P<a>\band|\bthen|,) (?:fly|drive|walk|wheel|roll|float|ride|move|bring|take) (?P<o>it|them) '
         r'(?:over |across |back |down |up |out |along )?(?P<p>to|into|onto)\b', r'\g<a> carry \g<o> \g<p>'),
    Rule('bring it home: home is where it goes',
         rf'\b(?P<v>take|bring|carry|return|get|haul|fetch) (?P<x>it|them|(?:the|a|an|my|your|our|this|that|'
         rf'these|'
         rf'those) {_NP}) (?:back )?home\b', r'\g<v> \g<x> to home'),
    Rule('take the chair back to the office',
         rf'\b(?P<v>take|bring|carry|return|move|haul|lug|wheel|ferry|cart) '
         rf'(?P<x>(?:the|a|an|my|your|our|this|that|'
         rf'these|those) {_NP}) back (?P<p>to|into|in|onto|inside)\b', r'\g<v> \g<x> \g<p>'),
    Rule('hold position over it, at inverter station 4: hover there (not "as long as b does not happen")',
         r'\bhold (?:your |its )?position '
         r'(?=over|above|there|here|for|(?:at|by|near|on) (?!.*\b(?:as long as|unless|until)\b))',
         'hover '),
    # "park yourself at the door until I tell you otherwise": the person's word is no event of the
    # task; what is said before it holds for the whole run
    Rule('stay at the door until I tell you otherwise',
         r'(?: ,)? (?:until|unless) (?:(?:i|we) (?:tell|say|call|radio|signal|let) (?:you )?(?:otherwise|'
         r'differently|so|know)|further (?:notice|instruction|instructions|orders)|(?:you are |you get )?'
         r'(?:told|instructed) otherwise|you hear otherwise|(?:you are |you get )?(?:told|instructed) to '
         r'move)\b',
         ''),
    Rule('survey the whole array: the array',
         r'\b(?P<v>survey|inspect|cover|scan|search|check|patrol|sweep|map|photograph|visit|over|around|'
         r'clean|'
         r'explore|circle|see|film|mow|tidy) (?P<d>the|that|this) (?:whole|entire) '
         r'(?!(?:time|way|trip|flight|route|mission|run|task|journey|drive|walk|tour|job|day|night|loop|'
         r'thing)\b)',
         r'\g<v> \g<d> '),
    Rule('hold off on it until you have been to X',
         rf'\b(?:hold off|wait) (?:on|with) (?:(?:going to|visiting|entering) )?(?P<x>it|them|there|{_NP}) '
         rf'(?=until|till|before|unless)',
         lambda m: f'do not go to {m.group("x") if m.group("x") != "there" else "it"} '),
    Rule('and before the closet, the laundry room: the goal before it',
         r'(?P<a>^|\band )(?P<c>before|after) (?P<x>(?:the|a|an|my|your|our) ' + _NP + r') , '
         r'(?P<y>(?:the|a|an|my|your|our) ' + _NP + r')$',
         r'\g<a>\g<c> going to \g<x> , go to \g<y>'),
    Rule('go to the bins at most once and to the pile twice: the verb said once',
         r'\b(?P<c>once|twice|thrice|times) (?P<j>and|but) (?P<p>to|into) (?=(?:the|a|an|my|your|our) )',
         r'\g<c> \g<j> go \g<p> '),
    Rule('and from there to the copier: the verb left out',
         r'(?P<a>(?:^|, )(?:and )?)from (?:there|here) (?=(?:to|on to|over to) (?:the|a|an|my|your|our) )',
         r'\g<a>then go '),
    Rule('visit a before b, and b before c: the verb said once',
         r'(?P<a>^(?:visit|go to) .* , (?:and|then) )(?P<x>(?:the|a|an|my|your|our) ' + _NP + r') '
         r'(?P<c>before|after) (?=(?:the|a|an|my|your|our) )',
         r'\g<a>visit \g<x> \g<c> '),
    Rule('visit the mailbox like at least twice: "like" says nothing',
         r'\blike (?=(?:at least|at most|exactly|once|twice|thrice|maybe|around|about|\d+|one|two|three|four|'
         r'five) )', ''),
    Rule('carry on to the lobby', r'\b(?:carry on|continue on|move on) (?=to |on to )',
         'go '),
    Rule('I need the stethoscope brought to the station',
         r'\b(?:i|we) (?:need|want|would like) (?P<x>(?:the|a|an|my|your|our|this|that) ' + _NP + r') '
         r'(?P<v>brought|taken|carried|moved|put|delivered) (?P<p>to|into|in|on|onto|over to|back to) ',
         lambda m: f'{_ACTIVE[m.group("v")]} {m.group("x")} {m.group("p")} '),
    Rule('before anything else, go to X: first', r'(?:^|(?<=, ))before (?:anything|everything) else (?:, )?',
         'first '),
    Rule('give the rug a wide berth',
         rf'\b(?:give|giving) (?P<x>{_NP}) a (?:wide|good|big|very wide) berth\b',
         r'keep away from \g<x>'),
    Rule('do not go near the server room without it: until you have it',
         r'\b(?P<a>(?:do not|never|you cannot|you must not) (?:go|enter|fly|walk|drive|head|'
         r'get)\b(?:(?! (?:then|and|but) ).)*?) without (?P<o>it|them)(?: (?:on you|with you|in hand))?$',
         r'\g<a> until you have \g<o>'),
    Rule('put the keys back and do not go through the server room doing it: the whole task',
         r'\b(?P<a>(?:do not|never|you cannot|you must not|avoid|stay|keep)\b(?:(?! (?:then|and|but) ).)*?)'
         r'(?: ,)? (?:while |when )?(?:doing (?:it|so|that|this|the job|the task)|'
         r'you do (?:it|so|that|this))$',
         r'\g<a> at any point'),
    Rule('only once rows 10 and 11 are done: only after them',
         rf'\bonly (?:once|when|after) (?P<x>(?:the |my |our )?{_NPS}) (?:are|is|have been|has been) '
         r'(?:both |all )?(?:done|checked|finished|complete|completed|visited|surveyed|inspected|covered)\b',
         r'only after \g<x>'),
    Rule('stay the hell away from the jack: stay away from it',
         r'\b(?P<v>stay|keep|get|steer) the (?:hell|heck|fuck|frick) (?=away|out|off|clear|back)\b',
         r'\g<v> '),
    Rule('do not cut across the lawn', r'\b(?:cut|shortcut|short cut) (?:across|through|over)\b',
         'go through'),
    Rule('the drone must survey the field, then it must land',
         r'(?P<pre>^|, |\bthen |\band )(?:the )?(?:robot|drone|it) (?:must|should|has to|needs to|will|'
         r'shall) ',
         r'\g<pre>'),
    Rule('climb to level four, drop to the second floor slab: go there',
         r'\b(?:climb|drop|descend|ascend|rise) (?:up )?to(?= (?:the|level|floor|roof|my|our|your)\b)',
         'go to'),

    Rule('the 2 nd floor', rf'\b(?P<n>{_SMALL}) (?:st|nd|rd|th) floor\b',
         lambda m: f'{_ORDINAL_OF[m.group("n")]} floor'),

    Rule('after seeing b',
         r'\b(?P<c>after|before|until|once|when) (?:seeing|observing|visiting|reaching|going to)\b',
         r'\g<c> you visit'),
    Rule('leave it and never go back', r'\b(?:and |then )*never (?:go|come) back(?: there| to it)?(?= ,|$)',
         ' , do not revisit it , '),
    Rule('visit c, in turn only visit b after a', r'\b(?:,? )?in turn\b', ' , '),
    Rule('visit a then b while ensuring not to visit b before a',
         r'\b(?:while|and) (?:ensuring|making sure)\b', ' , '),
    Rule('once the predecessor is visited you must visit the successor',
         r'\b(?:once|after|when) (?:the|a|each) predecessor is visited,? you (?:must|have to|should) visit '
         r'(?:the|its) successor\b', ' , in strict order , '),

    # ---- counts said as ranges
    Rule('zero times, once or twice',
         rf'\b(?:zero|0|no) times?(?: ,)?(?: (?:or )?(?:once|twice|thrice|{_NUM} times?)(?: ,)?)+', _upto),
    Rule('equal or less than twice', r'\bequal (?:to )?or (?:less|fewer) than\b', 'at most'),
    Rule('equal or more than twice', r'\bequal (?:to )?or (?:more|greater) than\b', 'at least'),
    Rule('five or more visits to X',
         rf'\b(?P<c>{_NUM}) or more {_KIND}(?P<u>visits|trips|passes) (?=to |through )',
         lambda m: f'at least {m.group("c")} {m.group("u")} '),
    Rule('two or more times', rf'\b(?P<c>{_NUM}) (?:times )?or more(?: {_KIND}{_UNIT})?\b',
         lambda m: f'at least {_times(_number(m.group("c")))}'),
    Rule('any more or any fewer than twice', r'\b(?:any )?(?:more|greater) or (?:any )?(?:fewer|less) than\b',
         'exactly'),
    Rule('at most and at least twice', r'\bat (?:most and at least|least and at most)\b', 'exactly'),
    # "visit the den and the hall, each exactly once": the count of each, said after them
    Rule('the den and the hall, each exactly once',
         r' , each (?P<m>(?:exactly|at least|at most) )?(?P<c>once|twice|thrice|(?:two|three|four) times)'
         r'(?= [.;!?]|$)', r' \g<m>\g<c> each'),
    Rule('but two times at most', rf'\b(?:but )?(?:only )?(?P<c>{_COUNT}) at (?P<m>most|least)\b',
         r'at \g<m> \g<c>'),
    Rule('on at least three separate occasions',
         rf'\bon (?P<mode>(?:at least|at most|exactly|any more than|more than|any fewer than|fewer than|'
         rf'less than) )?(?P<c>{_NUM}) {_KIND}(?:occasions?|instances?|times)\b',
         lambda m: f'{_group(m, "mode").replace("any ", "")}{_times(_number(m.group("c")))}'),
    Rule('for more than one distinct visit',
         rf'\bfor (?P<mode>more than |at least |at most |exactly )?(?P<c>{_NUM}) {_KIND}(?:visits?|times)\b',
         lambda m: f'{_group(m, "mode")}{_times(_number(m.group("c")))}'),

    # ---- counts said with a noun
    Rule('the maximum number of visits to X is three',
         rf'\bthe (?P<bound>maximum|max|minimum|min|required|exact) (?:allowable |allowed |permitted )?'
         rf'(?:number of )?{_KIND}(?:visits|passes|trips) (?:to|through|of|at) (?P<x>{_NP}) '
         rf'(?:is|are|should be|must be) (?:exactly )?(?P<n>{_NUM}|once|twice)\b', _bound),
    Rule('the maximum number of times you can visit X is three',
         rf'\bthe (?P<bound>maximum|max|minimum|min|required) (?:allowable |allowed |permitted )?number of '
         rf'times (?:that )?you (?:can|must|may|should|are allowed to|have to|need to) {_GO} (?P<x>{_NP}) '
         rf'(?:is |are )?(?:exactly )?(?P<n>{_NUM}|once|twice)\b', _bound),
    Rule('max one visit to the gate, only one trip to the dock: a count on its own',
         rf'(?:^|(?<=, ))(?P<bound>max|maximum|at most|no more than|only|just|at least|min|minimum|exactly) '
         rf'(?P<n>{_NUM}|a|a single|one single) {_KIND}(?:visits?|trips?|passes|stops?) '
         rf'(?:to|through|at|in) (?P<x>(?:the|my|your|our) {_NP})(?= [,.;]|$)',
         _bound),
    Rule('make at least three separate visits to X',
         rf'\b(?:make|complete|have|need|pay|do)(?P<only> only)? (?P<mode>(?:at least|at most|exactly|only|'
         rf'no more than|no fewer than|no less than) )?(?P<n>{_NUM}|a|an|single|any single) {_KIND}'
         rf'(?:visits?|trips?|passes) (?:to|through|of|at) (?P<x>{_NP})(?= |$)', _visits),

    # ---- counts said as a lock
    Rule('visiting X twice locks it for future visits',
         rf'\b(?:{_GOING}|passing through) (?P<x>{_NP}) (?:(?P<n>{_NUM}|twice|thrice|once)(?: times)? |for '
         rf'the (?P<o>{_ORD}) time )?(?:will )?locks? it(?: for (?:all )?future visits)?\b',
         lambda m: f'visit {m.group("x")} at most {_times(_number(m.group("o") or m.group("n") or "once"))}'),
    Rule('once you leave X for the second time you cannot come back to it',
         rf'\bonce you (?:leave|exit|enter|visit|reach) (?P<x>{_NP}) for the (?P<n>{_ORD}) time (?:, )?'
         rf'(?:you (?:cannot|can not|can never|must not|may not|should not) (?:come back|return|go back|'
         rf'reenter|re enter|enter|visit|go)(?: to| into)? it(?: again)?|it is locked(?: for you)?)\b',
         _locks),
    Rule('never visit X again after you have visited it three times',
         rf'\b(?:never|do not|you cannot|you can not) {_BACK} (?P<x>{_NP}) again after (?:you )?'
         rf'(?:have |haven |had )?{_GONE} (?:it|(?P=x)) (?P<n>{_COUNT})\b',
         lambda m: f'visit {m.group("x")} at most {_times(_count_of(m.group("n")))}'),
    Rule('once you reach X you can never visit it again',
         rf'\bonce you (?:have )?(?:{_GO}|{_GONE}) (?P<x>{_NP}) (?:, )?(?:you (?:can never|cannot|can not|'
         rf'must never|must not|should never|may not)|never) {_BACK} (?:it|(?P=x)) '
         rf'(?:again|anymore|any more)\b',
         r'visit \g<x> at most once'),
    Rule('visiting X more than twice is prohibited',
         rf'^(?P<verb>{_GOING}) (?P<rest>.+?) (?:is|are) {_FORBIDDEN}$',
         lambda m: f'do not {_plain(m.group("verb"))} {m.group("rest")}'),
    Rule('go to X more or less than twice is prohibited',
         rf'^(?P<verb>{_GO}) (?P<rest>.+?) (?:is|are) {_FORBIDDEN}$',
         r'do not \g<verb> \g<rest>'),
    Rule('go to X then leave it and repeat this two more times',
         rf'\b{_GO} (?P<x>{_NP})(?: ,)?(?: and)?(?: then)? leave(?: (?P=x)| it)?(?: and)*(?: then)? '
         rf'repeat(?: this| that| it)? (?P<mode>exactly |at least )?(?P<n>{_NUM}|once) more(?: times?)?\b',
         _repeat),
    Rule('at least twice, leaving in between',
         r'\b(?:while |by )?leaving(?: (?:its region|the region|it|there))? in between\b', ''),
    Rule('stop visiting it anymore', rf'\bstop (?P<verb>{_GOING}) (?P<x>it|{_NP}) (?:anymore|any more)\b',
         lambda m: f'do not {_plain(m.group("verb"))} {m.group("x")} anymore'),

    # ---- no revisits: "visit each location only once", "no revisiting", "without returning to X"
    Rule('visit each landmark only once',
         rf'(?:\byou can |\band |\bwhile )?(?:only )?(?:visit|visiting|go to|going to) (?:each|every|all)'
         rf'(?: of the| the| of)? {_PLACES} (?:only )?(?:exactly )?(?:once|one time|a single time)\b',
         _NO_REVISITS),
    Rule('no revisiting is allowed',
         r'\b(?:and |but )?no revisit(?:ing|s)? (?:is |are )?(?:allowed|permitted)(?: here)?\b',
         _NO_REVISITS),
    Rule('without returning to previously visited locations',
         rf'\bwithout (?:any )?(?:repetitions?|repeating|revisits|(?:skipping or )?revisiting any(?: one)? '
         rf'of them|(?:revisiting|returning to) (?:any )?previously visited {_PLACES})\b', _NO_REVISITS),
    Rule('once you leave any location you cannot return to it',
         rf'\bonce you leave any {_PLACES} you cannot (?:return|go back|come back) to it\b', _NO_REVISITS),
    Rule('do not revisit any of the locations before completing the task',
         r'\b(?:make sure to |ensure to )?(?:do not|not|never) revisit any(?: one)? of (?:them|the locations|'
         r'the places)(?: once after you have been there| before completing the task| after you have been '
         r'there)?\b', _NO_REVISITS),
    Rule('you cannot revisit a before completing the task',
         rf'\b(?:also )?(?:you cannot|you can not|you must not|do not|never|not|(?:ensure|make sure) '
         rf'(?:to not|not to)) (?:revisit|return to|go back to|come back to) (?P<x>{_NPS})(?: again)?'
         rf'(?: before (?:completing|finishing) (?:the )?(?:remaining )?tasks?)?{_CLAUSE_END}',
         r' , do not revisit \g<x> , '),
    Rule('you can only enter the bedroom once',
         rf'\byou (?:can|may) only (?P<v>{_GO}) (?P<x>{_NPS}) (?P<c>once|twice|thrice|{_NUM} times)(?= |$)',
         r'\g<v> \g<x> at most \g<c>'),
    Rule('go to b without returning to a',
         rf'\b(?:(?:but )?without|(?:, )?(?:or|nor)) (?:returning|going back|coming back|revisiting|'
         rf'revisit|return|go back|come back)(?: to)? (?P<x>{_NPS}){_CLAUSE_END}',
         r' , do not revisit \g<x> , '),
    Rule('go to b without going to a again', rf'\bwithout {_GOING} (?P<x>{_NPS}) again{_CLAUSE_END}',
         r' , do not revisit \g<x> , '),
    Rule('a followed by visiting b', rf'\bfollowed by {_GOING}\b', 'followed by'),
    Rule('make sure not to visit waypoints out of turn',
         r'\b(?:make sure|ensure)(?: not)? to (?:not )?visit (?:waypoints|locations|places|them) out of '
         r'(?:turn|order)\b', ' , in strict order , '),

    Rule('make sure to go there', r'\b(?:be sure|make sure|ensure|remember)(?: that)?(?: you)? to\b', ''),

    Rule('after you drop the box at the desk, go to the door',
         rf'^after you (?:have )?(?P<v>drop off|dropped off|drop|dropped|deliver|delivered|put|leave|left|'
         rf'bring|brought|take|took|place|placed) (?P<x>{_NPS}) (?P<p>at|in|on|to|into|onto) (?P<y>{_NPS}) , '
         rf'(?P<rest>(?:go|head|come|return|move|fly|visit|bring|take|put|drive|walk) .+)$',
         lambda m: f'{_PRESENT.get(m.group("v"), m.group("v"))} {m.group("x")} {m.group("p")} '
                   f'{m.group("y")} , then {m.group("rest")}'),

    # ---- passive goals and avoidances
    Rule('the shed must be visited',
         rf'(?P<pre>^|, |\bsure (?:that )?|\bensure (?:that )?)(?P<x>{_NPS}) (?P<aux>{_PASSIVE}) '
         rf'(?:all |both |each )?(?:visited|reached|entered|checked on|checked|inspected|looked at)(?= |$)',
         lambda m: f'{m.group("pre")}{"" if m.group("aux") in _PLAIN_AUX else "you must "}visit '
                   f'{m.group("x")}'),
    Rule('the shed must be avoided',
         rf'(?P<pre>^|, |\bsure (?:that )?|\bensure (?:that )?)(?P<x>{_NPS}) (?:always )?{_PASSIVE} '
         rf'(?:always )?avoided(?= |$)', r'\g<pre>avoid \g<x>'),


    Rule('the shed can never be visited',
         rf'(?P<pre>^|, |\bsure (?:that )?|\bensure (?:that )?|\bbut )(?P<x>{_NPS}) '
         rf'(?:can never|cannot|can not|must not|must never|should not|should never|may not|may never|'
         rf'shall not) '
         rf'(?:be )?(?:visited|reached|'
         rf'entered|approached)(?= |$)', r'\g<pre>you cannot visit \g<x>'),

    # ---- events said of the place
    Rule('until the gate is reached',
         rf'\b(?P<c>{_WHEN}) (?P<x>{_NPS}) (?:is|are|has been|have been|gets|get|was|were) '
         rf'(?:all |both |each |first |successfully )?(?:visited|reached|seen|observed|entered|encountered|'
         rf'detected|found|true|spotted)(?= |$)', r'\g<c> you visit \g<x>'),
    Rule('once the alarm occurs',
         rf'\b(?P<c>{_WHEN}) (?P<x>{_NPS}) (?:occurs|happens|holds|holds true|is true|becomes true|'
         rf'has occurred|has occured|has happened|appears|shows up)(?= |$)', r'\g<c> you visit \g<x>'),
    Rule('after you observe X',
         rf'\b(?P<c>{_WHEN}|sure|ensure|that) you (?:have |had )?(?:see|saw|seen|observe|observed|encounter|'
         rf'encountered|spot|spotted|notice|noticed|detect|detected)\b', r'\g<c> you visit'),

    # ---- conditions on order: "visit b only if you have been to a", "do not visit b if you have not seen a"
    Rule('only if you have been to X',
         rf'(?<!\band )\bonly if you (?:have |had )?(?:already |first )?(?:{_GONE}|{_GO})\b',
         'only after you visit'),
    Rule('if you have not been to X', rf'\bif you (?:have not|haven not|did not|have never|had not) (?:yet )?'
         rf'(?:{_GONE}|{_GO})\b', 'unless you visit'),

    Rule('do not stop until you visit a and b', r'\b(?:do not|never) stop until you visit\b', 'visit'),

    # ---- prohibitions said before their end: "until you have seen b, you cannot go to a"
    Rule('until you see b, you cannot go to a',
         rf'^(?P<u>(?:until|till) you (?:have |had )?(?:{_GONE}|{_GO}) {_NPS})(?: ,)? (?P<neg>(?:you cannot|'
         rf'you can not|you must not|'
         rf'do not|never|you should not|you may not)) (?P<v>{_GO}) (?P<y>{_NPS})$',
         r'\g<neg> \g<v> \g<y> \g<u>'),
    Rule('seeing b unlocks a',
         rf'^(?:{_GOING}|seeing|observing|visiting) (?P<x>{_NPS}) unlocks (?P<y>{_NPS})$',
         r'do not visit \g<y> until you visit \g<x>'),

    # ---- waiting somewhere until something happens: all become "stay at Y until you visit X"
    Rule('until you see b, stay at a',
         rf'^(?:until|till) you visit (?P<x>{_NPS})(?: ,)? (?:you must |you should |please )?'
         rf'(?P<stay>{_STAY} (?:at|in|on)|(?:do not|never|you cannot) (?:leave|exit)) (?P<y>{_NPS})$',
         r'\g<stay> \g<y> until you visit \g<x>'),
    Rule('you can leave a after b is seen, otherwise stay at a',
         rf'^(?:once you visit (?P<x1>{_NPS})(?: ,)? )?(?:you can |you may |feel free to |then )*leave'
         rf'(?: {_NP})?(?: after you visit (?P<x2>{_NPS}))?(?: ,)? otherwise {_STAY} (?:at|in|on) '
         rf'(?P<y>{_NPS})$',
         lambda m: _wait(m) if m.group('x1') or m.group('x2') else m.group(0)),
    Rule('hold position at a for as long as b does not occur',
         rf'^{_STAY} (?:at|in|on) (?P<y>{_NPS}) (?:for )?as long as (?:you do not {_SEE} (?P<x1>{_NPS})|'
         rf'(?P<x2>{_NPS}) (?:does|do) not {_HAPPEN})$', _wait),
    Rule('as long as you do not see b, do not leave a',
         rf'^as long as (?:you do not {_SEE} (?P<x1>{_NPS})(?: happen| occur)?|(?P<x2>{_NPS}) (?:does|do) '
         rf'not {_HAPPEN})(?: ,)? (?:do not|never|you cannot) (?:leave|exit) (?P<y>{_NPS})$', _wait),
    Rule('you cannot go anywhere from a unless you see b',
         rf'\b(?:you cannot|you can not|do not|never) (?:go|move|leave)(?: to)? (?:anywhere(?: else)?|'
         rf'any other places?|other places?|elsewhere) from (?P<y>{_NPS}) (?:unless|until|before) '
         rf'(?:you visit (?P<x1>{_NPS})|having (?P<x2>{_NPS}) (?:observed|seen|visited))$', _wait),

    # ---- order said at length
    Rule('in no particular order',
         r'\b(?:but )?(?:it can be done )?in (?:no (?:specific|particular)|an? (?:arbitrary|random)|any|'
         r'whatever|whichever|arbitrary|random) (?:order|sequence)(?: you (?:like|want|prefer|choose))?\b',
         'in any order'),
    Rule('there can be other places in between',
         r'\bthere (?:can|may|could|might) be other (?:locations|landmarks|places|waypoints|stops|rooms) '
         r'in between\b', ''),
    Rule('go to four locations a, b, c and d',
         rf'\b(?P<head>all |the following |all the following |these |all of the )?(?:{_NUM}) '
         rf'(?P<what>locations|places|landmarks|rooms|spots|waypoints)(?: :)?(?= |$)', r'\g<head>\g<what>'),
    Rule('go to one of a and b and then to the other',
         rf'\b(?:go to|visit|pick) one (?:of|from|among) (?P<x>{_NP}) and (?P<y>{_NP})(?: ,)? (?:go there )?'
         rf'(?:and )?then (?:go |head |move )?to the other(?: one)?\b', r'visit \g<x> and \g<y>'),

    # ---- repetition said at length: "again and again", "with no limits", "at any point in time, visit a"
    Rule('all the time do not go close to X: "all the time" before a rule is "always"',
         r'\b(?:all the time|(?:in|during|for) (?:the )?(?:whole|entire) time)(?: ,)? '
         r'(?=(?:do not|never|avoid|stay|keep|steer)\b)', 'always '),
    Rule('visit a again and again', r'\b(?:again and again|over and over(?: again)?|with no limits?|without '
         r'(?:any )?limits?|time after time|all the time)\b', 'repeatedly'),
    Rule('exactly twice, not once, not three times: exactly twice',
         rf'(?P<e>\bexactly (?:(?:{_SMALL}|\d+) (?:times|visits|trips|passes)|once|twice|thrice)\b'
         rf'(?: [a-z_]+){{0,4}}?)(?: ,)? not (?:once|twice|thrice|{_SMALL}|\d+)(?: times)?'
         rf'(?:(?: ,)? (?:and |or )?not (?:once|twice|thrice|{_SMALL}|\d+)(?: times)?)*\b', r'\g<e>'),
    Rule('at any point in time you must visit a at least once in the future',
         rf'\b(?:make sure )?(?:at any point in time|at every point in time|at all times|at any time)(?: ,)? '
         rf'(?:you (?:will |must |should |have to )?|ensure that you (?:will )?|'
         rf'make sure (?:that )?you (?:will )?)?'
         rf'(?:visit|go to|reach) (?P<x>{_NPS}) at least once (?:in the future|after|afterwards|later)\b',
         r'visit \g<x> repeatedly'),
    # ---- found on blind sets H to K
    Rule('would you be a dear and go',
         r'\b(?:(?:would|could|will) you )?be a (?:dear|star|love|darling) and\b', ''),
    Rule('bring in the post and put it on the table: the particle before the thing',
         r'\b(bring|fetch|carry|get) (?:in|inside|up|down|over|along) (?=(?:the|my|your|our|his|her) )',
         r'\1 '),
    Rule('do keep away from the radiator: an emphatic "do"',
         r'(?<!you )\bdo (?:please )?(?=(?:keep|stay|avoid|go|bring|take|visit|come|check|head|remember|'
         r'steer|fly|be)\b)', ''),
    Rule('making your way to the desk',
         r'\bmak(?:e|ing) (?:your|its) way (?:over |back |down |up |across )?(?=to\b)', 'go '),
    Rule('only go to the top field once you have done the drill',
         r'\b(?P<w>once|when|after|until|till) you have (?:done|finished|checked|sorted) '
         r'(?=(?:the|my|our|your) )',
         r'\g<w> you have visited '),
    Rule('maintain distance from the cables',
         r'\b(?:maintain|keep) (?:a |your )?(?:safe |good |wide )?distance (?:away )?from\b',
         'keep away from'),
    Rule('or else the green one', r'\bor else\b', 'or'),
    Rule('put the keys either in the bowl or in the drawer',
         r'\b(?P<v>put|place|bring|take|leave|drop|set) (?P<o>(?:the|my|your|a|an|this|that|those|these) '
         r'(?:[a-z0-9_]+ ){0,3}?[a-z0-9_]+) either (?P<p>in|on|into|onto|to|at|by|inside|under) ',
         r'\g<v> \g<o> \g<p> either '),
    Rule('only after stopping at the back door: the event said with -ing',
         r'\b(?P<w>after|before|until|till) (?:stopping|passing|checking|calling|looking) '
         r'(?:in |out )?(?:at|by|over|through|past|on|in at|into)\b', r'\g<w> visiting'),
    Rule('go back and forth between the desk and the printer twice',
         r'\bgo back and forth between (?P<a>(?:the|my|your) (?:[a-z0-9_]+ ){0,3}?[a-z0-9_]+) and '
         r'(?P<b>(?:the|my|your) (?:[a-z0-9_]+ ){0,3}?[a-z0-9_]+) (?P<c>twice|thrice|[a-z0-9]+ times)\b',
         r'go from \g<a> to \g<b> \g<c> in a row'),
    Rule('you must stay by the QA bench: be there',
         r'(?:^|(?<=^now )|(?<=, )|(?<=\band )|(?<=\bthen ))(?:you (?:must|should|need to|have to) )?'
         r'(?:stay|stand|sit) (?=(?:by|next to|beside) (?:the|my|your|our)\b)', 'go '),
    Rule('go sit by the couch',
         r'\bgo (?:and )?(?:sit|stand|wait|park|hover|stay) (?=(?:by|next to|near|beside|at) )', 'go '),
    Rule('the register last: the last of a sequence',
         r'(?P<j>, and |, then |, | and | then )(?P<x>(?:the|my|your) (?:[a-z0-9_]+ ){0,3}?[a-z0-9_]+) last$',
         r'\g<j>finally \g<x>'),
    Rule('go first to the skeleton, after to the gift shop: "after" for "then"',
         r' , after (?=to )', ' , then '),
    Rule('should you need to pass through the kitchen at all: "if"',
         r'\bshould you (?:need to |have to |want to |happen to |ever )?', 'if you '),
    Rule('carry it to the shed and drop it there: one delivery',
         r'\b(?P<d>(?:to|into|onto|on|in|up to|over to) (?:the|my|your|our) (?:[a-z0-9_]+ ){0,4}?[a-z0-9_]+)'
         r'(?: ,)? and (?:then )?(?:drop|leave|put|set|place|release|dump|stash) (?:it|them) (?:down |off )?'
         r'(?:there|in there|on there)\b', r'\g<d>'),
    Rule('between those two, stay clear of the door: the leg to the last goal',
         r'(?<!leg )(?<!way )(?<!stretch )(?<!part )(?<!bit )\bbetween (?:those|these|the) two'
         r'(?: (?:places|stops|goals|points|spots))?\b(?! (?!is\b|was\b)[a-z]+s\b)', 'on the way there'),
    Rule('between the desk and the waiting room, keep away from X: that leg of the route',
         r'^between (?P<a>(?:the|my|your) (?:[a-z0-9_]+ ){0,3}?[a-z0-9_]+) and '
         r'(?P<b>(?:the|my|your) (?:[a-z0-9_]+ ){0,3}?[a-z0-9_]+) ,', r'on the way from \g<a> to \g<b> ,'),
    Rule('and the yoga mat after that: "after that" said after the goal',
         r'(?P<j>(?:, )?(?:and|then) )(?P<x>(?:the|my|your|our) (?:[a-z0-9_]+ ){0,3}?[a-z0-9_]+) after '
         r'(?:that|this|it)(?= ,| \.|$)', r'\g<j>after that \g<x>'),
    Rule('after the reception, go to the coffee machine: the reception first',
         r'^(?:so |and |then )?after (?P<x>(?:the|my|your|our) (?:[a-z0-9_]+ ){0,3}?[a-z0-9_]+) , '
         r'(?=(?:go|head|fly|visit|come|drive|move|proceed|check|land|stop|swing|pop)\b)',
         r'go to \g<x> , then '),
    Rule('go to the copier and after to the printer, and after bring the report: "after" alone is "then"',
         r'(?P<j>, |\band )after (?=(?:to|go|come|land|fly|head|return|again|back|visit|check|drive|move|'
         r'proceed|finish|continue|stop|swing|pop|over|through|past|into|onto|bring|take|carry|deliver|fetch|'
         r'grab|pick|put|place|drop|throw|toss|hover|survey|inspect|patrol)\b)', r'\g<j>then '),
    Rule('and the other two you avoid: the thing avoided said first',
         r'(?P<j>(?:^|, |\band |\bbut ))(?P<x>(?:the|my|your|our) (?:[a-z0-9_]+ ){0,8}?[a-z0-9_]+) (?:you|u) '
         r'(?P<v>avoid|never go to|never visit|do not go to|do not visit|do not go near|stay away from|'
         r'keep away from)(?= [.;!?]|$)', r'\g<j>\g<v> \g<x>'),
    Rule('first you go to the lathe, after you go to the mill: the second after the first',
         r'^(?P<a>first (?:you )?(?:go|head|fly|drive|move|come) [^,]*) , (?:and )?after you '
         r'(?=(?:go|head|fly|drive|move|come)\b)(?!.* , )', r'\g<a> , then you '),
    Rule('check the balcony and after the terrace: then the terrace',
         r'\band after (?P<x>(?:the|my|your|our) (?:[a-z0-9_]+ ){0,3}?[a-z0-9_]+)(?= ,| \.|$| and\b)',
         r'and then \g<x>'),
    Rule('and at the end to my office: finally',
         r'\b(?:at the end|in the end|at last|to finish|lastly) '
         r'(?=(?:to|go|come|return|back|land|fly|head)\b)',
         'finally '),
    Rule('only once you have been by the fuse box: only after',
         r'\bonly once (?=(?:you|we|the robot|it|i) )', 'only after '),
    Rule('during the carrying: while carrying it',
         r'\b(?:during|for) (?:the )?(?:carrying|carry|transport|transportation|delivery)\b',
         'while carrying it'),
    Rule('run the lobby then mail room then loading dock route: the places in that order',
         rf'\b(?:do|walk|run|drive|fly|make|complete|follow|take|patrol) (?:the|that|this|a) '
         rf'(?P<l>{_W}(?: {_W}){{0,3}}(?: (?:,|then|, then|and then) (?:the )?{_W}(?: {_W}){{0,3}}?){{1,6}}) '
         r'(?:loop|route|run|circuit|round|sequence|course)\b(?! (?:from|to)\b)',
         lambda m: 'go to the ' + _in_order(m.group('l'))),
    Rule('do the back porch to shed run: from the porch to the shed',
         r'\b(?:do|make|walk|run|fly) the (?P<a>(?:[a-z0-9_]+ ){0,3}?[a-z0-9_]+) to (?:the )?'
         r'(?P<b>(?:[a-z0-9_]+ ){0,3}?[a-z0-9_]+) (?:run|loop|route|circuit|lap|trip|leg)\b',
         r'go from the \g<a> to the \g<b>'),
    Rule('airlift the kit to the pump station, fly the sensor to the mast: carrying it there',
         rf'\b(?:airlift|air lift|sling|winch|fly) (?P<x>it|them|(?:the|a|an|my|your|our|this|that|'
         rf'these|those) {_NP}) (?P<p>(?:over |across |up |down )?(?:to|into|onto))\b', _carried),
    Rule('land it on the canteen roof: put it there',
         r'\b(?:land|lower|winch|set) (?P<o>it|them) (?:down )?'
         r'(?=(?:on|onto|at|in|into) (?:the|my|your|our)\b)',
         r'put \g<o> '),
    Rule('avoid the lines while it is slung underneath: while carrying it',
         r'\b(?:while|as long as) (?:it is|they are|the load is) (?:still )?(?:slung|hanging|attached|'
         r'on board|aboard|loaded|being carried|held|in tow|in the (?:gripper|claw|basket|sling|winch|hook))'
         r'(?: (?:underneath|below|beneath|under the drone|under you|under it))?\b', 'while carrying it'),
    Rule('two times back to back: twice in a row',
         r'\b(?:two times|twice|2 times) (?:back to back|consecutively|one after the other|straight)\b',
         'twice in a row'),
    Rule('loop a, b, c, and run that loop twice: twice in a row',
         r'(?: ,)? (?:and )?(?:then )?(?:run|do|fly|walk|drive|complete|make) (?:that|the|this) '
         r'(?:same |whole )?'
         r'(?:loop|route|circuit|round|run|sequence|course|lap) (?P<n>twice|two times|2 times)(?= \.|$)',
         ' twice in a row'),
    Rule('loop crane 1, crane 2, site office: the places in that order',
         rf'^loop (?:through |around |round )?(?P<l>(?:the )?{_W}(?: {_W}){{0,3}}(?: (?:,|then|, then|, and|'
         rf'and then) (?:the )?{_W}(?: {_W}){{0,3}}?){{1,6}})(?= twice in a row\b|$)',
         lambda m: 'go to ' + _in_order(m.group('l'))),
    Rule('do not approach the office nor the glass wall: or',
         r'^(?!.*\bneither\b)(?P<a>.*\b(?:not|never|avoid)\b.*?) nor (?=(?:the|my|your|a|an|our)\b)',
         r'\g<a> or '),
    Rule('visit the printer minimum two times: at least',
         r'\b(?:at minimum|minimum|at the minimum|a minimum of|min)\b(?= (?:one|two|three|four|five|once|'
         r'twice|thrice|[0-9]+)\b)', 'at least'),
    Rule('while you carry the motor to the test bench, avoid the wash station: the delivery, then its scope',
         rf'^(?:okay |so |now )?while (?:you )?(?:are )?(?:carry|carrying|bring|bringing|take|taking) '
         rf'(?P<x>(?:the|my|your|our) {_THING}) to (?P<y>(?:the|my|your|our) {_THING}) , '
         rf'(?P<r>(?:avoid|stay away from|keep away from|do not go near|never go near|keep clear of) '
         rf'(?:the|my|your|our) {_THING})$',
         r'bring \g<x> to \g<y> and \g<r> while carrying it'),
    Rule('go in the paint booth maximum one time: at most',
         r'\b(?:maximum|max)\b(?= (?:one|two|three|four|five|once|twice|thrice|[0-9]+)\b)', 'at most'),
    Rule('exactly two times, not more: said once',
         r'(?P<a>\bexactly (?:(?:one|two|three|four|five) times?|once|twice|thrice)) (?:, )?'
         r'(?:and )?(?:not|no|never) more(?: than that)?(?= [,.;]|$)', r'\g<a>'),
    Rule('only when you have been at the kit, you can go: only after',
         r'^only (?:when|once) (?=(?:you|we|the robot) )', 'only after '),
    Rule('only after you visit the kitchen you can go to the gym: the goal first (no comma between)',
         r'^(?:and |but |so )?only after (?P<e>(?:(?! only after | (?:you|we) (?:can|may) | then )[^,;])+?) '
         rf'{_ALLOWED} (?P<m>{_GOAL_VERB}\b(?:(?! only after ).)*)$',
         r'\g<m> , but only after \g<e>'),
    Rule('go to the gym not before going to the kitchen: but not before',
         rf'\b(?P<g>{_GO} {_NP}) not before (?=[a-z])', r'\g<g> but not before '),
    Rule('go to the gym after going to the kitchen, do not go to the gym before: not before it',
         rf'\b(?P<g>{_GO}) (?P<x>{_NP}) after (?P<e>(?:{_GOING}|you {_GO}|you have {_GONE}) {_NP}) '
         r'(?:, )?(?:and |but )?'
         rf'(?:do not|never) {_GO} (?P=x) (?:before|earlier|sooner|first)$',
         r'\g<g> \g<x> but not before \g<e>'),
    Rule('only after you have been to the kitchen, you can go to the gym: the goal first',
         rf'^(?:and |but |so )?only after (?P<e>[^,;]+?) (?:, )+(?:then )?(?:{_ALLOWED} )?'
         rf'(?P<m>{_GOAL_VERB}\b.*)$', r'\g<m> , but only after \g<e>'),
    Rule('fly until the clock tower: to it',
         r'\b(?P<v>fly|go|drive|walk|come|head|move|travel|proceed) until (?=(?:the|my|your|our)\b)',
         r'\g<v> to '),
    Rule('the plant at the left side of the elevator: left of it',
         r'\b(?:at|on|to) the (?P<s>left|right)(?: hand)?(?: side)? of\b', r'\g<s> of'),
    Rule('the plant which is standing left of the elevator: which is',
         r'\b(?P<w>which|that) (?:is )?(?:standing|stands|stays|staying|sitting|sits|lying|lies|located|'
         r'placed|'
         r'kept|resting|rests)\b', r'\g<w> is'),
    Rule('the laptop is on the ottoman; go to it: where a thing is, said as a statement',
         rf'^(?:and |so |well )?(?P<x>(?:the|my|your|our|a|an) {_THING}) '
         rf'(?:is|are|should be|must be|might be|'
         rf'may be|is probably|sits|lies|stands|is sitting|is lying|is standing|is kept|was left|got left|'
         rf'is still|is somewhere) '
         rf'(?P<r>{_WHERE} (?:the|my|your|our) (?!(?:[a-z0-9_]+ ){{0,3}}?floor\b){_THING}'
         rf'(?: and (?:the|my|your|our) {_THING})?)(?= [,;]|$)',
         r'there is \g<x> \g<r>'),
    Rule('behind the sofa there is a cable',
         rf'^(?P<r>{_WHERE} (?:the|my|your|our) {_THING})(?: ,)? there (?:is|are) '
         rf'(?P<x>(?:a|an|the|some|two) '
         rf'{_THING})(?= [,;]|$)', r'there is \g<x> \g<r>'),
    Rule('and on that stretch keep away from the door: on the way there',
         r'\bon (?:that|this|the) (?:second |last |final |next |same )?'
         r'(?:stretch|leg|part|bit|segment|section)'
         r'(?: of the (?:route|trip|way|journey|flight|run))?\b', 'on the way there'),
    Rule('go to the grill, but the patio table has to come first: only after it',
         rf'(?P<j>, |; )(?:but |and )?(?P<x>(?:the|my|your|our) {_THING}) (?:has to|must|needs to|should|'
         rf'has got to|is to) (?:come|be visited|be done|be checked|go|happen|be) first\b',
         r'\g<j>but only after \g<x>'),
    Rule('save the gym for after the office: only after it',
         rf'\b(?:save|leave|keep|hold) (?P<x>(?:the|my|your|our) {_THING}) (?:for|until|till|to) after\b',
         r'only go to \g<x> after'),
    Rule('avoid a the whole time, and b too: a and b the whole time',
         r'(?P<d> (?:the whole time|the entire time|at all times|throughout|the whole way|the entire way)) '
         r', and (?P<y>(?:the|my|your|our) [a-z0-9_ ]+?) (?:too|as well|also)(?= [,.;]|$)',
         r' and \g<y>\g<d>'),
    Rule('heading over to the booth, keep clear of the fountain: on the way to it',
         r'\b(?:while |when |as )?(?:you are |you re )?(?:heading|going|walking|driving|flying|moving|'
         r'travelling|traveling|making your way) (?:over |back |across |down |up |on )?to '
         r'(?P<x>(?:the|my|your|our) [a-z0-9_ ]+?) , (?P<v>keep clear of|avoid|stay away from|'
         r'keep away from|steer clear of|do not go near|stay clear of|keep out of|stay out of|do not pass)\b',
         r'on the way to \g<x> \g<v>'),
    Rule('fly out and survey the farm: survey it',
         r'\b(?:fly|head|go|drive|walk|zip|pop|nip) (?:out|off|over|up) (?:and |to )'
         r'(?=(?:survey|visit|inspect|check|go|fly|look|scan|photograph|map|patrol|film|circle|hover)\b)',
         ''),
    Rule('go to the seat and the chair, the chair first: the chair, then the seat',
         r'\b(?P<v>go to|visit|check|stop at|hit) (?:both )?(?P<a>(?:the|my|your|our) [a-z0-9_ ]+?) and '
         r'(?P<b>(?:the|my|your|our) [a-z0-9_ ]+?) , (?:the |my |your |our )?(?P<c>[a-z0-9_ ]+?) first'
         r'(?=$| , (?:and |but )?(?:do not|never|avoid|stay|keep|steer)\b)',   # (a rule may follow)
         _named_first),
    Rule('only if you actually need to go into the room: if you go into it',
         r'^(?:only )?if you (?:actually |really |ever |do )?(?:need|have|want|got) to '
         r'(?P<v>go into|enter|go in|go inside|step into|go to|visit|use|pass through|go through)\b'
         r'(?P<x>[^:,;]*?) (?::|,)',
         r'if you \g<v>\g<x> ,'),
    Rule('hit the sanitizer before you step inside: first',
         r' before (?:you|we) (?:step|go|head|walk|get|move|pop|nip) '
         r'(?:inside|in|into it|in there|into the room)'
         r'(?= [,.;]|$)', ' first'),
    Rule('fly to the field, power lines are dangerous so keep away: the power lines',
         r'(?P<p>^|, )(?P<x>(?!(?:the|my|your|our|a|an|it|they|there|this|that|you|i|we|he|she|everything|'
         r'nothing|something|what|which|who)\b)[a-z_]+(?: [a-z_]+)?) (?P<v>is|are) '
         r'(?=(?:dangerous|hazardous|unsafe|fragile|slippery|live|off limits|out of bounds)\b[^.;]* so\b)',
         r'\g<p>the \g<x> \g<v> '),
    Rule('that plant on the filing cabinet - once at most: visit it so often',
         rf'^(?:that|this|the) (?P<x>{_THING}(?: (?:on|by|next to|under|behind|near|in) (?:the|my|your|our) '
         rf'{_THING})?) (?:-|,|:) (?P<c>(?:(?:at most|at least|exactly|only|no more than) )?'
         rf'(?:once|twice|thrice|{_NUM} times)(?: at most| at least| exactly| only| max)?)\b',
         r'visit the \g<x> \g<c>'),
    Rule('go see what is up at the espresso maker: go to it',
         r'\b(?:go |and )*(?:go to|see|check|find out|look at) what (?:is|s) (?:up|going on|happening|wrong) '
         r'(?:at|with|by|in|near|over at) (?=(?:the|my|your|our)\b)', 'go to '),
    Rule('but wait until you have checked the window first: only after',
         r', (?:but |and )?wait until (?P<w>you have|you ve|you) '
         r'(?P<v>checked|visited|been to|seen|reached|inspected)'
         r'(?P<x> (?:the|my|your|our) [a-z0-9_ ]+?)(?: first)?(?= [,.;]|$)',
         r', but only after \g<w> \g<v>\g<x>'),
    Rule('only after checking the oven: after you have been there',
         r'\b(?P<w>only after|after|before|until|not before|not until) '
         r'(?:checking|visiting|inspecting|seeing|'
         r'looking at|checking on|stopping at|stopping by)(?: out)? (?=(?:the|my|your|our)\b)',
         r'\g<w> you have been to '),
    Rule('the green locker comes only after the blue one: visit it only after',
         rf'(?P<p>^|, and |; )(?P<x>(?:the|my|your|our) {_THING}) (?:comes |goes |is )?only after ',
         r'\g<p>visit \g<x> only after '),
    Rule('stay away from the dog, it is a guide dog, leave it be: avoid it (the avoidance said again)',
         r'(?P<a>\b(?:avoid|(?:stay|keep|steer) (?:away|clear|well away|well clear) (?:from|of)|'
         r'do not go near) [^.;!?]*?) (?:, |and |, and )(?:just |please )?leave (?P<p>it|them) (?:alone|be)'
         r'(?= [,.;!?]|$)',
         r'\g<a> , avoid \g<p>'),
    Rule('go to it exactly once, then leave it alone: never again',
         r'(?: ,)? (?:and )?(?:then )?(?:leave (?:it|them) (?:alone|be)|never again)(?= [,.;]|$)',
         ' and never go there again'),
    Rule('the cereal box goes back in the pantry: put it there',
         rf'^(?P<x>(?:the|my|your|our|this|that|these|those) {_THING}(?: and (?:the|my|your|'
         rf'our) {_THING})?)'
         rf'(?: both| all)? (?:goes|go|belongs|belong|need to go|needs to go|should go|has to go|have to go|'
         rf'must go)(?: back)?(?: out)? (?P<p>in|into|on|onto|to|inside|under)\b',
         _put_or_move),
    Rule('wait at the stool: go there (to wait until something is a rule of its own)',
         r'^(?!.*\b(?:until|till|unless|before)\b)(?P<a>(?:.* )?)wait (?:at|in) (?=(?:the|my|your|our) )',
         r'\g<a>go to '),
    Rule('do not go down the front hallway: the hallway as a place',
         r'\bgo (?:down|along|up|through) '
         r'(?=(?:the|my|your|our) (?:[a-z0-9_]+ ){0,2}?(?:hallway|hall|corridor|'
         r'street|path|road|alley|aisle|lane|passage|driveway)\b)', 'go to '),
    Rule('do not cut through the garden to get there: on the way there',
         r'(?: ,)? (?:to get there|getting there|while getting there|as you get there|on your way there|'
         r'to reach it|reaching it)(?= [,.;]|$)', ' on the way there'),
    Rule('do not bump into the bicycles: go near them',
         r'\b(?:bump|bumping|crash|crashing|run|running) into\b',
         'go near'),
    Rule('the treadmill can wait until you have been to the dispenser: not before',
         rf'^(?P<x>(?:the|my|your|our) {_THING}) (?:can|will have to|has to|must|should|needs to) wait '
         rf'(?=(?:until|till)\b)', r'do not go to \g<x> '),
    Rule('then leave by either the north exit or the south exit: going to the exit',
         r'\b(?:leave|exit) (?:by|via|through) (?=(?:either )?the )', 'go to '),
    Rule('go to the guest room, but hold off until you have been to the bathroom: not until',
         r'(?<=, )(?:but )?hold off(?: on (?:that|it|going there))? (?:until|till)(?= you| i| we)',
         'not until'),
    Rule('once you have been to the basket, and not before, go to the footstool: only after',
         r'^(?:once|after|when) (?P<e>[^,]+?) , (?:and )?not (?:before|earlier|sooner)(?: that)? , '
         r'(?P<m>.+)$',
         r'\g<m> , but only after \g<e>'),
    Rule('either of the east gate and the south gate: either the one or the other',
         rf'\b(?:either|any one|any|one|whichever) of (?P<a>(?:the|my|your|our) {_NP}) and '
         rf'(?P<b>(?:the|my|your|our) {_NP})(?= is| are| will| works| [,.;]|$)', r'either \g<a> or \g<b>'),
    Rule('go to either elevator bank, east or west: the east elevator bank or the west elevator bank',
         rf'\beither (?:the |one )?(?P<n>{_W}(?: {_W}){{0,2}}) , (?:the )?(?P<a>{_SIDE})(?: one)? (?P<j>or) '
         rf'(?:the )?(?P<b>{_SIDE})(?: one)?(?= [,.;]|$)',
         lambda m: 'either ' + _each_named(m)),
    Rule('the east or the west nurses station: each named in full',
         rf'\bthe (?P<a>{_SIDE}) (?P<j>or|and) (?:the )?(?P<b>{_SIDE}) '
         rf'(?P<n>[a-z0-9_]+(?: [a-z0-9_]+){{0,2}}?)'
         rf'(?= [,.;]|$| and\b| or\b| then\b| but\b| first\b| whichever\b| if\b)',
         _each_named),
    Rule('stay away from the wires until you get there: on the way there',
         r'\buntil (?:you|we|the robot) (?:get there|arrive(?: there)?|are there|make it there|reach it|'
         r'get to it)(?= [,.;]|$)', 'on the way there'),
    Rule('the north or the south stairwell, and keep out of the lobby until you are in one of them: on the '
         'way there (to whichever of the choice is reached)',
         r'\bor\b(?P<x>[^.;?!]*?)\buntil (?:you|we|the robot) (?:are in|are at|get to|get into|reach|'
         r'arrive at|make it to|are inside|enter) (?:one|either|any) of (?:them|those|the two)'
         r'(?= [,.;]|$)', r'or\g<x>on the way there'),
    Rule('avoid the gate the whole time, and the kiosk on the way there: the verb said again',
         rf'\b(?P<v>avoid|keep away from|stay away from|keep clear of|steer clear of|stay clear of|'
         rf'stay out of|keep out of|keep off|stay off|do not go near) (?P<x>(?:the|my|your|our) {_NP})'
         rf'(?P<d> (?:the whole time|the entire time|at all times|throughout|the whole way|the entire way|'
         rf'at any point|at any time)) , and (?P<y>(?:the|my|your|our) {_NP}) '
         rf'(?=(?:on the way|until|till|before|after|once|while)\b)',
         r'\g<v> \g<x>\g<d> , and \g<v> \g<y> '),
    Rule('not before you visited the changing room and also the shower: and',
         r'\band also (?=(?:the|my|your|our)\b)', 'and '),
    Rule('it must be only one of the two, never both of them: not both',
         r'\bnever both(?: of them| of those| of the two)?\b', 'not both'),
    Rule('go exactly one time to the coffee machine: the count after the place',
         rf'\b(?P<v>go|fly|stop|head|come|drive) (?P<c>exactly |at least |at most |only )?'
         rf'(?P<n>once|twice|thrice|'
         rf'(?:one|two|three|four|five) times?) (?P<p>to|at|by|over|past) (?P<x>(?:the|my|your|our) {_THING}'
         rf'(?: {_WHERE} (?:the|my|your|our) {_THING})?)'   # "go two times to the valve under the tank"
         rf'(?= [,.;]|$| and\b| then\b)', r'\g<v> \g<p> \g<x> \g<c>\g<n>'),
    Rule('and after the second time go to the copier: then',
         r'(?: ,)? (?:and )?after the (?:second|third|fourth|2nd|3rd) (?:one|pass|visit|time|lap|round)'
         r'(?: ,)? '
         r'(?=(?:go|return|head|fly|land|come|drive|proceed|move)\b)', ' , then '),
    Rule('check the heater, the detector, and then the fuse box: one after the other',
         rf'(?P<a>(?:the|my|your|our) {_THING}) , (?P<b>(?:the|my|your|our) {_THING})(?: ,)? and then '
         rf'(?=(?:the|my|your|our|go|come|head|back|return|visit|check|finally)\b)',
         r'\g<a> , then \g<b> , and then '),
    Rule('gallery 3, gallery 4, then the print room: one after the other',
         rf'(?P<a>(?:(?:(?:the|my|your|our) {_THING}|{_LABELLED}) , )+)'
         rf'(?=(?:(?:the|my|your|our) {_THING}|{_LABELLED}) , then (?:(?:the|my|your|our) |{_LABELLED}\b))',
         lambda m: m.group('a') if _RULE_BEFORE.search(m.string, 0, m.start()) else
         m.group('a').replace(' , ', ' , then ')),
    Rule('throw it out: away', r'\b(?P<v>throw|toss|chuck) (?P<o>it|them) (?:out|away)\b',
         r'\g<v> away \g<o>'),
    Rule('i need the tape measure and the hammer in the garage: bring them there',
         rf'^(?:i|we) (?:need|want|would like) (?:both )?(?P<x>(?:the|my|your|our) {_THING}'
         rf'(?: and (?:the|my|your|our) {_THING})?) (?:in|on|at|by) (?P<y>(?:the|my|your|our) {_THING})$',
         r'bring \g<x> to \g<y>'),
    Rule('the coat stand is where I want you: go there',
         rf'^(?P<x>(?:the|my|your|our) {_THING}) is where (?:i|we) (?:want|need) (?:you|the robot)'
         rf'(?: to (?:be|go))?(?= -| ,| ;|$)', r'go to \g<x>'),
    Rule('keeping away from the flagpole while it is in your grip: while carrying it',
         r'\bwhile (?:it is|they are) (?:in your (?:grip|hands|hand|claws|gripper|arms|grasp)|being carried|'
         r'on board|aboard)\b', 'while carrying it'),
    Rule('drop it off, keeping away from the flagpole: keep away',
         r', (?:keeping|staying|steering) (?=(?:away|clear)\b)', ', keep '),
    Rule('inspect the tank before the chimney, and the chimney before the dish: the verb said again',
         r'^(?P<h>(?!visit\b)[a-z]+(?: [a-z]+)? (?:(?:the|my|your|our) )?[a-z0-9_ ]+? before '
         r'(?:(?:the|my|your|our) )?[a-z0-9_ ]+?) , and (?=(?:(?:the|my|your|our) )?[a-z0-9_ ]+? before )',
         r'\g<h> , and visit '),   # "do lane 2 before lane 1, and lane 1 before ...": also with no article
    Rule('the aquarium and the bird cage are off limits: avoid both',
         rf'^(?P<x>(?:the|my|your|our) {_THING}(?: , (?:the|my|your|our) {_THING})*(?: ,)? and '
         rf'(?:the|my|your|our) {_THING}) are (?:both |all )?'
         rf'(?:off limits|out of bounds|forbidden|not allowed|'
         rf'banned|a no go|no go|dangerous|unsafe)(?P<t>(?= until| till| before| once| after| when| for)|$)',
         r'avoid \g<x>'),
    Rule('then drop down to the third floor: go there',
         r'\b(?:drop|come|go|fly|climb|descend|head|move) (?:back )?down to\b', 'go to'),
    Rule('you may go out on the balcony: go there',
         r'\bgo out (?:on|onto|to|into) (?=(?:the|my|your|our)\b)', 'go to '),
    Rule('when you leave the porch for the shed, keep away from the bed: on that leg',
         rf'\b(?:when|while|as) you (?:leave|go from|head from|fly from|move from) (?P<a>(?:the|my|your|our) '
         rf'{_THING}) (?:for|to|towards|toward) (?P<b>(?:the|my|your|our) {_THING})(?= ,)',
         r'on the way from \g<a> to \g<b>'),
    Rule('either inspect the billboard first and then the gas station, or the other way round',
         rf'^(?:either )?(?P<v>go to|visit|inspect|check|fly over|fly to|survey|stop at) '
         rf'(?P<a>(?:the|my|your|our) {_THING})(?: first)? (?:and )?then (?:to )?'
         rf'(?P<b>(?:the|my|your|our) {_THING})(?: ,)? or (?:do it |go )?'
         rf'(?:the other way (?:round|around)|vice versa|in the opposite order|the reverse|in reverse)$',
         r'either \g<v> \g<a> and then \g<b> , or \g<v> \g<b> and then \g<a>'),
    Rule('go to the den then the hall, or the hall then the kitchen: one route or the other',
         rf'^(?P<v>go to|visit|inspect|check|fly over|fly to|survey|stop at) '
         rf'(?P<a>(?:the|my|your|our) {_THING}) (?P<t1>(?:and )?then) (?:to )?'
         rf'(?P<b>(?:the|my|your|our) {_THING})'
         rf'(?: ,)? or (?:go to |visit )?(?P<c>(?:the|my|your|our) {_THING}) (?P<t2>(?:and )?then) (?:to )?'
         rf'(?P<d>(?:the|my|your|our) {_THING})$',
         r'either \g<v> \g<a> \g<t1> \g<b> , or \g<v> \g<c> \g<t2> \g<d>'),
    Rule('go to the last one first, and after it the first one: then',
         r'\band after (?:it|that|this|them) (?=(?:the|my|your|our)\b)', 'and then '),
    Rule('dont go near it while your carrying it: you are',
         r'\b(?P<w>while|when|as) your (?=(?:carrying|holding|moving|taking|bringing|transporting|going|'
         r'heading|returning|walking|flying|driving|there|on)\b)', r'\g<w> you are '),
    Rule('but only go to the lab once you have been to the supply room: only after',
         rf'\bonly (?P<v>go|head|visit|enter|come|fly) (?P<r>(?:to |into |in )?(?:the|my|your|our) {_THING}) '
         rf'once (?=(?:you|we|the robot) )', r'\g<v> \g<r> only after '),
    Rule('check one of the printers, the colour one or the laser one: either',
         rf'\bone of the (?:two |three )?[a-z]+s , (?=(?:the|my|your|our) {_THING} or )', 'either '),
    Rule('and from there to the packing area keep away from the conveyor: on the way there',
         rf'(?P<j>, (?:and )?|\band )(?:then go|from there) to (?P<b>(?:the|my|your|our) {_THING}) '
         rf'(?=(?:do not|never|avoid|stay away|keep away|steer clear|keep clear)\b)',
         r'\g<j>then go to \g<b> , and on the way there '),
    Rule('go to the patio, though you have to visit the grill first: only after',
         rf', (?:though|but|although|and) (?:you|we) (?:have to|must|need to|should|will have to) '
         rf'(?:visit|go to|stop at|check|see|pass by|hit) (?P<x>(?:the|my|your|our) {_THING}) '
         rf'first(?= [,.;]|$)',
         r', but only after \g<x>'),
    Rule('wait until you have been to the mudroom before going into the kitchen: only after',
         rf'^wait until (?P<e>you (?:have|ve) [a-z ]+? (?:the|my|your|our) {_THING}) before (?:going|heading|'
         rf'moving|you go) (?:into|to|in|inside) (?P<x>(?:the|my|your|our) {_THING})$',
         r'go to \g<x> , but only after \g<e>'),
    Rule('without ever getting close to the candles: near them',
         r'\bwithout (?P<e>ever )?(?:getting|going|coming|moving) (?:too )?(?:close to|near|next to)\b',
         lambda m: f'without {m.group("e") or ""}going near'),
    Rule('en route to the bathroom: on the way', r'\ben route (?=to\b)', 'on the way '),
    Rule('once you get there the shredder is off limits',
         rf'^(?P<w>(?:once|after|when) you (?:get|are|have got|have gotten|arrive|reach|have reached|have'
         rf' arrived)'
         rf'(?: there| here| in| at| to)?) (?:, )?(?P<x>(?:the|my|your|our) {_THING}) (?:is|are) '
         rf'(?:off limits|out of bounds|forbidden|not allowed|a no go)\b', r'\g<w> , avoid \g<x>'),
    Rule('from then on, the desk lamp is off limits: avoid it from then on',
         rf'^(?P<w>from then on|from that point on|from that point onwards|from then onwards|after that|'
         rf'from there on|from there onwards|'
         rf'afterwards|thereafter) (?:, )?(?P<x>(?:the|my|your|our) {_THING}) (?:is|are) '
         rf'(?:off limits|out of bounds|'
         rf'forbidden|not allowed|a no go)(?=$| (?:, )?(?:so|and) )', r'\g<w> , avoid \g<x>'),
    # ("after that the front door is off limits, so head up to the stairs": the goal is in its scope too)
    Rule('once it is in your hands: once picked up',
         r'\b(?P<c>once|when|after) (?:it is|they are) '
         r'(?:in your (?:hands|hand|grip|gripper|possession|arms)|'
         r'on board|aboard|picked up)\b', r'\g<c> you have picked it up'),
    Rule('until it is in your gripper: until picked up',
         r'\b(?P<c>until|till) (?:(?:it is|they are) (?:in your (?:hands|hand|grip|gripper|possession|arms)|'
         r'on board|aboard)|you have (?:it|them) in (?:hand|your hands?|your gripper|your grip))\b',
         r'\g<c> you have picked it up'),
    Rule('for the rest of the task: from then on',
         r'(?: ,)? (?:for the rest of the (?:task|trip|run|mission|job|day|way)|'
         r'for the remainder(?: of the task)?)'
         r'(?= [,.;]|$)', ''),
    Rule('but not to both: not both', r'\bnot (?:to|at|into) both\b', 'not both'),
    Rule('you can stop at the snack cabinet (if you want), but never more than once: at most once',
         rf'\b(?:you can|you may|feel free to) (?P<v>stop at|visit|go to|pass by|swing by|check) '
         rf'(?P<x>(?:the|my|your|our) {_THING})(?: if you (?:want|like|wish))?(?: ,)? (?:but )?'
         rf'(?:(?:never|not|no) more than once|only once at most|at most once|only once)\b',
         r'\g<v> \g<x> at most once'),
    Rule('go to the bench, the shelf, the lamp and finally the exit: one after the other', _LIST_THEN,
         _in_turn),
    Rule('and to the turnstile you go only after: go to it',
         rf'\b(?P<j>and |, )?to (?P<x>(?:the|my|your|our) {_THING}) you (?:go|may go|can go|should go)\b',
         r'\g<j>go to \g<x>'),
    Rule('bring at my desk the bottle or the can: the thing, then where',
         rf'\b(?P<v>bring|take|put|carry|deliver) (?:at|to) (?P<d>(?:the|my|your|our) {_THING}) '
         rf'(?P<o>(?:the|a|an|my|your|our) {_THING}(?: (?:or|and) (?:the|a|an|my|your|our) {_THING})?)'
         rf'(?= [,.;]|$)',
         r'\g<v> \g<o> to \g<d>'),
    Rule('or otherwise go to the legal office: or', r'\bor (?:otherwise|else|alternatively)\b', 'or'),
    Rule('only enter the workshop after visiting the kit, though you do not have to go in at all: if at all',
         rf'^only (?:enter|go to|go into|visit) (?P<x>(?:the|my|your|our) {_THING}) after '
         rf'(?:visiting|checking|going to|stopping at|you visit|you have visited|you check|you go to) '
         rf'(?P<y>(?:the|my|your|our) {_THING}) , (?:though|but|and) you do not (?:have|need) '
         rf'to (?:go into|go to|enter|visit|go in)(?: (?:the|my|your|our) {_THING}| it| there)?(?: at all)?$',
         r'if you go into \g<x> at all , visit \g<y> first'),
    Rule('I would be very grateful if you went over to the cupboard: please go',
         r'\b(?:i would|i d|we would|we d) be (?:very |so |really |most |ever so )?(?:grateful|glad|happy|'
         r'pleased) '
         r'if you (?:could |would )?(?:went|go|head|headed|made your way|popped|nipped)\b', 'please go'),
    Rule('making sure you have checked the ticket office before that: only after',
         r'(?: ,)? (?:making sure|make sure|being sure|ensuring) (?P<e>you (?:have|ve) [a-z]+ (?:the|my|your|'
         r'our) '
         r'(?:[a-z0-9_]+ ){0,3}?[a-z0-9_]+) (?:before that|beforehand|first)(?= [,.;]|'
         r'$)', r' , but only after \g<e>'),
    Rule('nip out through the north door: go through',
         r'\b(?:nip|pop|duck|slip|step) (?:out |over |across |round |down |up )?(?P<p>through|to|into|'
         r'over to)\b',
         r'go \g<p>'),
    Rule('exactly twice, once in the morning and once at night: the count said again, spread over the day',
         rf'\b(?P<c>(?:twice|thrice|{_NUM} times)) , (?P<s>once {_DAYTIME}(?: (?:, |and |, and )?once '
         rf'{_DAYTIME}){{1,3}})(?= [,.;!?]|$)',
         _spread),
    Rule('more than once in total: the count said once',
         r'(?<=\bonce) in total\b|(?<=\btimes) in total\b', ''),
    Rule('go to the crib but hit the table and the pail first, any order: only after both',
         rf'(?P<g>(?:go to|visit|head to|get to) (?:the|my|your|our) {_THING})(?: ,)? but (?:hit|visit|check|'
         rf'go to|'
         rf'stop at|do) (?P<x>(?:the|my|your|our) {_THING}(?: and (?:the|my|your|our) {_THING})?) first'
         rf'(?: ,)?(?: in any order| any order| in either order|'
         rf' either order)?$', r'\g<g> , but only after \g<x>'),
    Rule('go on to the vault, where the archivist is waiting with a flask of tea: who is there',
         r' , where (?:the|a|an|my|our|your) [a-z ]+? (?:is|are|will be) (?:waiting|sitting|working|standing|'
         r'expecting you|ready)(?: [a-z ]+)?(?= [.;!?]|$)', ''),
    Rule('cereal box back into the pantry, please: put it there',
         r'^(?!(?:[a-z0-9_]+ ){0,4}(?:heading|going|coming|way|walking|driving|flying|moving|you|are|make|'
         r'making|get|getting)\b)'
         r'(?P<x>(?:the |my )?(?!(?:do|go|come|get|head|and|then|not|never|please|you|we|i|just|put|take|'
         r'while|when|on|as|once|after|before|if|until|till|bring|'
         r'move|carry|fly|drive|tidy|clear|pack|throw|toss)\b)[a-z0-9_]+(?: [a-z0-9_]+){0,3}?) back '
         r'(?P<p>into|in|onto|on|to) '
         r'(?=(?:the|my|your|our)\b)',
         r'put \g<x> back \g<p> '),
    Rule('visit the pantry and the garage, and go to the fridge last: after all the others',
         rf'^(?P<pre>.*\b(?:the|my|your|our) [a-z].*?) (?P<v>go to|visit|check|stop at|end at|finish at|'
         rf'head to) '
         rf'(?P<x>(?:the|my|your|our) {_THING}) (?:last|last of all|at the very end)(?= [,.;]|$)',
         r'\g<pre> \g<v> \g<x> . \g<x> is last'),
    Rule('potting bench first, vegetable patch second, rain barrel last: in turn',
         rf'^(?P<a>(?:the |my )?{_THING}) first , (?P<b>(?:the |my )?{_THING}) (?:second|next|'
         rf'then) , (?:and )?'
         rf'(?P<c>(?:the |my )?{_THING}) (?:last|third|'
         rf'finally)$', r'go to \g<a> , then to \g<b> , then to \g<c>'),
    Rule('go to the mailbox once, exactly once: exactly once',
         r'\bonce (?:, |- )?(?:exactly|precisely) once\b', 'exactly once'),
    Rule('there should be a blanket on the ottoman: there is',
         r'\bthere (?:should|must|might|may|could|will) be\b',
         'there is'),
    Rule('stop there only the one time: exactly once',
         r'\b(?P<m>more than |no more than |not more than )?(?:only )?(?:the one time|a single trip|'
         r'one single trip)\b',
         # ("not more than the one time": a bound, once)
         lambda m: f'{m.group("m")}once' if m.group('m') else 'exactly once'),
    Rule('wait for me by the back porch, meet me at the bike rack: go there',
         r'\b(?:wait (?:for (?:me|us|them|him|her)|there)|meet (?:me|us|them|him|her)) '
         r'(?:by|at|near|next to|in|on|outside)\b', 'go to'),
    Rule('though you have to hit the fuse box before you set foot there: only after',
         rf', (?:though|but|although|and) (?:you|we) (?:have to|must|need to|should) (?:visit|go to|stop at|'
         rf'check|'
         rf'hit|see) (?P<x>(?:the|my|your|our) {_THING}) (?:before you (?:set foot|go|step) (?:in )?(?:there|'
         rf'in there|'
         rf'inside))(?= [,.;]|$)', r', but only after \g<x>'),
    Rule('but make sure you have hit both the washer and the dryer first: only after',
         rf'(?:,|\bbut|, but) (?:make sure|be sure|check) (?:that )?you (?:have|ve) (?:hit|visited|been to|'
         rf'checked|seen|'
         rf'stopped at) (?:both )?(?P<x>(?:the|my|your|our) {_THING}(?: and (?:the|my|your|'
         rf'our) {_THING})?) first'
         rf'(?= [,.;]|$)', r', but only after \g<x>'),
    Rule('the tennis ball rolled behind the armchair: it is there',
         rf'^(?P<x>(?:the|my|your|our|a|an) {_THING}) (?:rolled|slid|ended up|'
         rf'has rolled) (?P<r>{_WHERE} (?:the|my|your|our) {_THING})(?= [,.;]|$)', r'there is \g<x> \g<r>'),
    Rule('I just need you at the sink: I need you there',
         r'\b(?P<s>i|we) (?:just|only|really|actually|simply|mainly) (?=(?:need|want|'
         r'would like) )', r'\g<s> '),
    Rule('where did I leave my charger? go look for it: it is somewhere',
         rf'^where (?:did|have|has) (?:i|we|you|somebody|someone) (?:leave|left|put|drop|dropped|hide|stash) '
         rf'(?P<x>(?:my|the|our|your|a) {_THING})$', r'there is \g<x>'),
    Rule('where did the remote end up? go find it: it is somewhere',
         rf'^where (?:did|has|have|would|is|are) (?P<x>(?:my|the|our|your) {_THING}) (?:end up|ended up|go|'
         rf'gone|get to|'
         rf'got to|disappear to|disappeared to|wander off to|vanish to)$', r'there is \g<x>'),
)

_SENTENCE_ENDS = frozenset('.;!?')


# each rule with the literal text any match of it needs (a sentence without it is not tried)
_COMPILED = tuple((re.compile(r.pattern), r.replacement, required_text(r.pattern)) for r in RULES)


_LEVEL_RE = re.compile(rf'\blevel (?P<m>{_SMALL})\b')


def levels_as_floors(tokens: list[str]) -> list[str]:
    """Read "level two" as "second floor" (a set's convention; otherwise "level two" is the name said)."""
    if 'level' not in tokens:
        return tokens
    return _LEVEL_RE.sub(lambda m: f'{_ORDINAL_OF[m.group("m")]} floor', ' '.join(tokens)).split()


def rewrite_idioms(tokens: list[str]) -> list[str]:
    """Rewrite each sentence's idioms to their canonical phrasing (see :data:`RULES`)."""
    out: list[str] = []
    start = 0
    for i, t in enumerate(tokens + ['.']):
        if t in _SENTENCE_ENDS:
            out.extend(_rewrite_sentence(tokens[start:i]))
            out.extend(tokens[i:i + 1])
            start = i + 1
    return out


def _rewrite_sentence(words: list[str]) -> list[str]:
    if not words:
        return []
    text = ' '.join(words)
    for pattern, replacement, needs in _COMPILED:
        if admits(needs, text):
            text = pattern.sub(replacement, text)
    return text.split()
