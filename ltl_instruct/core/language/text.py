"""Text normalisation for the offline translator: lower case, typos, contractions, tokens.

The offline translator reads a token list, never the raw string. This module
turns what people type (contractions, chat spelling, small typos, ordinals such
as ``2nd``, punctuation runs) into that token list. Punctuation that carries
structure (``, . ; : ! ?``) stays as its own token; everything else that is not
a letter or digit is dropped.
"""
from __future__ import annotations

import re
import unicodedata

# Chat spellings and typos seen in instructions to robots; whole-word replacements.
TYPOS: dict[str, str] = {
    'teh': 'the', 'hte': 'the', 'u': 'you', 'ur': 'you are', 'n': 'and', 'atleast': 'at least',
    'dont': 'do not', 'yerself': 'yourself', 'youre': 'you are', 'actualy': 'actually',
    'acutally': 'actually',
    'thrid': 'third', 'undr': 'under', 'vist': 'visit', 'pls': 'please', 'plz': 'please',
    'kitchn': 'kitchen', 'dishwsher': 'dishwasher', 'litterbox': 'litter box', 'doesnt': 'does not',
    'cant': 'cannot', 'wont': 'will not', 'im': 'i am', 'ive': 'i have', 'youve': 'you have',
    'theyve': 'they have', 'weve': 'we have',
    'thats': 'that is', 'theres': 'there is', 'somebodys': 'somebody is', 'someones': 'someone has',
    'dosent': 'does not', 'pleas': 'please', 'survery': 'survey', 'lol': '', 'rn': 'right now',
    'nevermind': 'never mind', 'untl': 'until', 'adn': 'and',
    'glu': 'glue', 'ther': 'there', 'thers': 'there is', 'nvm': 'never mind',
    'its': 'it is', 'didnt': 'did not', 'isnt': 'is not',
    'goto': 'go to', 'infront': 'in front', 'nxt': 'next', 'frist': 'first', 'secnd': 'second',
    'avoiid': 'avoid', 'aviod': 'avoid', 'fridg': 'fridge', 'bathrom': 'bathroom', 'thn': 'then',
    'tonite': 'tonight', 'nite': 'night', 'lest': 'least', 'idc': 'i do not care', 'idk': 'i do not know',
    'omg': 'oh',
    'rwo': 'row',
    'untill': 'until', 'til': 'until', 'till': 'until', 'b4': 'before', 'w': 'with', 'thru': 'through',
    'ok': 'okay', 'tv': 'tv', 'behing': 'behind', 'betwen': 'between', 'betweeen': 'between',
    'nevr': 'never', 'alway': 'always', 'alwasy': 'always', 'twond': 'second', 'oppposite': 'opposite',
    'ofthe': 'of the', 'tothe': 'to the', 'togo': 'to go', 'dnt': 'do not', 'bak': 'back',
    'visti': 'visit', 'vsit': 'visit', 'vist1': 'visit', 'gp': 'go', 'og': 'go',
    'util': 'until', 'onest': 'first', 'threerd': 'third', 'landark': 'landmark', 'occations': 'occasions',
    'occation': 'occasion', 'endlessy': 'endlessly', 'whichevers': 'whichever is', 'rtb': 'return to base',
    'rth': 'return to the home point',
    'kitchin': 'kitchen', 'livingroom': 'living room', 'diningroom': 'dining room', 'frontdoor': 'front door',
    'backdoor': 'back door', 'laundryroom': 'laundry room', 'guestroom': 'guest room',
    'frontyard': 'front yard',
    'bathroon': 'bathroom', 'bedrom': 'bedroom', 'hallwya': 'hallway', 'garagae': 'garage',
    'ovr': 'over', 'tims': 'times', 'tmes': 'times', 'nexto': 'next to', 'nextto': 'next to',
    'vaccum': 'vacuum', 'vacum': 'vacuum', 'vaccuum': 'vacuum', 'trolly': 'trolley',
    'flashlite': 'flashlight',
    'tho': 'though', 'thx': 'thanks',
    'twise': 'twice', 'twic': 'twice', 'ovre': 'over', 'aera': 'area', 'carring': 'carrying', 'cary': 'carry',
    'meting': 'meeting', 'carryng': 'carrying', 'wiat': 'wait',
    'dinning': 'dining', 'glas': 'glass', 'bord': 'board', 'cupbord': 'cupboard', 'cubbord': 'cupboard',
    'backwrds': 'backwards', 'heatr': 'heater', 'mashine': 'machine', 'machin': 'machine',
    'fridege': 'fridge', 'frige': 'fridge', 'livng': 'living', 'ony': 'only', 'benind': 'behind',
    'sry': 'sorry', 'srry': 'sorry', 'nah': 'no', 'kyes': 'keys', 'whil': 'while',
    'exacty': 'exactly', 'rak': 'rack', 'dor': 'door', 'nex': 'next', 'exactley': 'exactly',
    'exacly': 'exactly',
    'fo': 'of', 'backwords': 'backwards', 'itme': 'item', 'itmes': 'items', 'rom': 'room', 'stn': 'station',
    'wya': 'way', 'sory': 'sorry',
    'jsut': 'just', 'hod': 'hood', 'retuning': 'returning', 'wich': 'which', 'whcih': 'which', 'frm': 'from',
    'flor': 'floor', 'revers': 'reverse',
    'abt': 'about', 'rm': 'room', 'bfore': 'before', 'aftr': 'after', 'agin': 'again',
    # chat spellings of "because" (a reason follows) and of a subject with its verb
    'bc': 'because', 'bcuz': 'because', 'becuz': 'because', 'cuz': 'because', 'coz': 'because',
    'uve': 'you have', 'hes': 'he is', 'shes': 'she is', 'theyre': 'they are', 'tmrw': 'tomorrow',
    'lmao': '', 'jk': 'just kidding', 'beetwen': 'between', 'bewteen': 'between', 'betwean': 'between',
    # well-known office and building abbreviations, spelled out in names ("conf rm B": conference_room_b);
    # not "exec", a word of its own ("the exec suite" is how people name it)
    'conf': 'conference', 'recep': 'reception', 'mtg': 'meeting', 'mtgs': 'meetings',
    'fl': 'floor', 'flr': 'floor', 'bldg': 'building', 'dept': 'department', 'mgr': 'manager',
    'rms': 'rooms', 'ppl': 'people',
}
# Places that are told apart by a number ("bay 4", "bed 11", "side room 2", "dock 3").
LABEL_HEADS = frozenset('''
bay bed room ward dock gate bench aisle level theatre bin zone area table desk locker shelf rack pod cubicle
booth pen stall platform lane lift wing block suite unit cell cabin cot stand bank lab station berth
'''.split())
# "away form the stove": after these words "form" is a slip for "from".
_FORM_RE = re.compile(r'\b(away|clear|far|apart|back|out|off|keep|stay|distance) form\b')
# "on your wat to the dining room": a slip in "on your way to" (one letter, a word of its own)
_WAY_RE = re.compile(r'\b(on (?:your|the|my|its) )(?:wat|wau|wy|wya|waay|wey)'
                     r'(?= (?:to|back|in|out|there|over)\b)')

# Chat shorthand written with a slash.
_SLASH_SHORT = {'w/e': 'whatever', 'w/o': 'without', 'b/c': 'because'}
_SLASH_SHORT_RE = re.compile(r'\b(?:w/e|w/o|b/c)\b')

# Family members named like names, with no article ("Mum's bedroom", "Dad always worries").
FAMILY_NAMES = frozenset({'mum', 'mom', 'mummy', 'mommy', 'dad', 'daddy', 'grandma', 'grandpa', 'granny',
                          'gran', 'grandad', 'granddad', 'nana', 'nan', 'papa', 'mama'})

CONTRACTIONS: tuple[tuple[str, str], ...] = (
    (r"\bdosn'?t\b", 'does not'), (r"\bdoesnt\b", 'does not'),
    (r"\bdosen't\b", 'does not'),
    (r"\bwon't\b", 'will not'), (r"\bcan't\b", 'cannot'), (r"\bdon't\b", 'do not'),
    (r"n't\b", ' not'), (r"'ve\b", ' have'), (r"'re\b", ' are'), (r"'ll\b", ' will'),
    (r"\bi'm\b", 'i am'),
    (r"'s(?= been\b)", ' has'),   # "until the truck's been inspected": "has", never "is been"
    (r"\b(that|there|it|what|where|here|who|he|she|how|why|when|everything|everyone|nothing|wherever|"
     r"whichever|whatever)'s\b", r'\1 is'),
    (r"\b(either|whichever|which|each|this|that|any|neither|first|second|third|last|other|middle|red|blue|"
     r"green|left|right|big|small) one's\b", r'\1 one is'),   # "either one's fine", "the first one's"
    # "either ones fine", as speech recognition writes it (the apostrophe lost)
    (r"\b(either|any|whichever) ones(?= (?:fine|ok|okay|good|alright|great)\b)", r'\1 one is'),
    (r"'s(?= (?:next|first|last|after|before|then)\b)", ' is'),   # "the drum kit's next"
    (r"\blet's\b", 'let us'),
    # "the table's fine", "the red one's locked": "is", not a possessive, before how a thing is
    (r"'s(?= (?:fine|ok|okay|alright|safe|locked|closed|shut|open|broken|blocked|up|out|off|empty|full|wet|"
     r"dirty|clean|busy|free|taken|packed|gone|not|too|very|really|still|already|been|being|actually|"
     r"no longer|now|dangerous|slippery|hot|cold|occupied|off limits|fragile|heavy|sharp|almost|nearly|dead|"
     r"low|flat|loose|wobbly|unstable|frayed|exposed|leaking|leaky|sticky|cracked|jammed|stuck|faulty|"
     r"unplugged|noisy|loud|messy|due|late|ready|done|finished)\b)", ' is'),
    (r"\b(one|two|three|four|five|six|once|twice)'s\b", r'\1 is'),   # "no, three's plenty"
    # "Stan's finished with it", "wherever Joan's sat": "has" before a past participle
    (r"'s(?= (?:finished|sat|gone|done|got|asked|said|told|come|arrived|fallen|moved|lost|forgotten|had|"
     r"eaten|started|stopped|seen|promised|decided|dropped|spilt|spilled)\b)", ' has'),
    # "grandma's sleeping": "is", before a verb in -ing (not "dad's walking stick")
    (r"'s(?= [a-z]+ing\b(?! (?:stick|sticks|machine|glasses|bag|board|table|room|chair|rod|frame|shoes|mat|"
     r"pole|line|basket|boots|gloves|kit|pad|area|station|cane|aid|lamp|desk|tray|can)\b))", ' is'),
    # "the dog's outside", "the cat's in the kitchen": "is", before where a thing is
    (r"'s(?= (?:outside|inside|here|there|away|asleep|awake|home|upstairs|downstairs|in|at|on|under|behind|"
     r"out|around|nearby|next to|by the)\b)", ' is'),
    # "my brother's drum kit": a person's things are named without the person (drum_kit)
    (r"\b(?:my|your|our|his|her|their) (?:little |big |older |younger |baby )?(?:brother|sister|mom|mum|dad|"
     r"mother|father|son|daughter|wife|husband|grandma|grandpa|grandmother|grandfather|aunt|uncle|cousin|"
     r"kid|boss|partner|roommate|flatmate|friend|girlfriend|boyfriend|neighbor|neighbour|colleague)'s\b",
     'the'),
    # "Mum's bedroom", "Dad's walking stick": a family member's things, named without them
    (r"\b(?:" + '|'.join(sorted(FAMILY_NAMES)) + r")'s\b", 'the'),
    # a possessive keeps its s, the apostrophe dropped ("the supervisor's desk": supervisors_desk;
    # "the kids' table": kids_table), as most golds written for us name them (17 of 24)
    (r"'d\b", ' would'), (r"'s\b", 's'), (r"s'(?=\s)", 's'),
)


# Names of three words joined by "of" ("chest of drawers"): one thing.
_OF_THINGS = {('suit', 'of', 'armor'): 'suit_of_armor', ('suit', 'of', 'armour'): 'suit_of_armour',
              ('chest', 'of', 'drawers'): 'chest_of_drawers', ('bag', 'of', 'flour'): 'bag_of_flour',
              ('pile', 'of', 'logs'): 'pile_of_logs', ('box', 'of', 'tissues'): 'box_of_tissues',
              ('chest', 'of', 'drawer'): 'chest_of_drawers', ('cup', 'of', 'tea'): 'cup_of_tea',
              ('glass', 'of', 'water'): 'glass_of_water', ('bottle', 'of', 'water'): 'bottle_of_water'}
# Things named with "stand" ("the umbrella stand next to the door"): one name, not the verb.
_STAND_THINGS = frozenset('''
umbrella music coat plant tv hat cake microphone mic bike display flower night fruit magazine newspaper lamp
easel book laptop monitor phone speaker guitar drum shoe boot wine key taxi bus lemonade kiosk news towel soap
menu
'''.split())


def join_compounds(tokens: list[str]) -> list[str]:
    """Join a name of several words into one ("umbrella stand": umbrella_stand; "chest of drawers")."""
    if 'stand' not in tokens and 'of' not in tokens:
        return tokens
    out: list[str] = []
    for t in tokens:
        if t == 'stand' and out and out[-1] in _STAND_THINGS:
            out[-1] = out[-1] + '_stand'
            continue
        if len(out) >= 2 and (out[-2], out[-1], t) in _OF_THINGS:
            out[-2:] = [_OF_THINGS[(out[-2], out[-1], t)]]   # "the chest of drawers"
            continue
        out.append(t)
    return out


ORDINAL_DIGITS: dict[str, str] = {
    '1st': 'first', '2nd': 'second', '3rd': 'third', '4th': 'fourth', '5th': 'fifth',
    '6th': 'sixth', '7th': 'seventh', '8th': 'eighth', '9th': 'ninth', '10th': 'tenth',
}

NUMBER_WORDS: dict[str, int] = {
    'one': 1, 'two': 2, 'three': 3, 'four': 4, 'five': 5, 'six': 6, 'seven': 7, 'eight': 8,
    'nine': 9, 'ten': 10, 'once': 1, 'twice': 2, 'thrice': 3, 'eleven': 11, 'twelve': 12, 'thirteen': 13,
    'fourteen': 14, 'fifteen': 15, 'sixteen': 16, 'seventeen': 17, 'eighteen': 18, 'nineteen': 19,
    'twenty': 20,
}

# The word for a number ("2": two), from the cardinals above.
_NUMBER_NAME: dict[int, str] = {n: w for w, n in NUMBER_WORDS.items() if w not in ('once', 'twice', 'thrice')}

ORDINALS: dict[str, int] = {
    'first': 1, 'second': 2, 'third': 3, 'fourth': 4, 'fifth': 5, 'sixth': 6, 'seventh': 7,
    'eighth': 8, 'ninth': 9, 'tenth': 10,
}

PUNCT = frozenset(',.;:!?')
_TOKEN_RE = re.compile(r"[a-z0-9]+(?:_[a-z0-9]+)*|[,.;:!?]")
# A verb and its particle joined by a hyphen name a kind of thing ("walk-in", "drop-off", "check-in").
_PARTICLE_COMPOUND_RE = re.compile(
    r'\b(walk|drive|drop|check|sign|pull|roll|pop|lean|built|fold|slide|pick|take|lay|top|stand|look|tip)-'
    r'(in|out|off|up|through|thru|to|down|over|by|away|on)\b(?=\s+[a-z])'
    # ... and any word before "-in", "-out", "-off" ("the goods-in door", "the roll-out bins")
    r'|\b([a-z]{3,})-(in|out|off)\b(?=\s+[a-z])')
# ... and after a determiner, a noun wherever it stands ("check the walk-in.", "to the drop-off?")
_NOUN_COMPOUND_RE = re.compile(r'\b(the|my|our|this|that) '
                               r'(?:(walk|drive|drop|check|pull|roll|pop|lean|look|tip)-'
                               r'(in|out|off|through|thru|up)'
                               r'|(walk|drive)(in|thru)|(drop)(off))\b')
# An acronym after a determiner ("the IT office", "the ER") is a name, not the word it spells.
_ACRONYM_RE = re.compile(
    r"\b(the|a|an|our|my|your|this|that)\s+(IT|US|ER|OR|AM|PE|PA|UN|HR)\b(?=\s+[A-Za-z])", re.IGNORECASE)

# ... and so is one in capitals opening a list item with a noun after it ("mail room / IT help desk").
_ITEM_ACRONYM_RE = re.compile(
    r"(?:^|[,:;/+&]\s*|\b(?:and|or|then|to|at|by|from|near|past|avoid)\s+)(IT|ER|OR|PE|HR)\b"
    r"(?=\s+(?!(?:is|was|will|has|had|should|must|can|could|would|does|did|may|might|needs|seems|"
    r"looks)\b)[a-z])")


# The hospital's accident and emergency department, said in capitals ("avoid A and E", "A&E").
# (not two labels: "fields A and E")
_A_AND_E_RE = re.compile(r'(^|[,.;:!?]\s*|\b(?i:the|to|at|of|in|by|from|near|past|into|avoid|floor|and|or)'
                         r'\s+)'
                         r'A ?(?:and|&|n|\+) ?E\b')
# A capital letter after a word names something ("field A", "Gate B"): not the article "a".
_LETTER_RE = re.compile(r"(?<=[a-z]) ([A-HJ-Z])(?=[\s,.;:!?)]|$)")


# "shelf B4" (in capitals, after any word), "bay b4" (after a noun that takes labels): a label, not
# the typed shorthand for "before".
_B4_RE = re.compile(r"(?<=[A-Za-z] )B4\b")
_B4_LABELLED = frozenset('''
shelf shelves aisle bay bin gate room locker seat row table dock box cell rack unit section slot cabinet
drawer stall platform bed desk level door hangar pod cage pen tank zone area lab office ward wing suite
booth counter station lane pallet pier berth bench building block spot shelving hall stand pad classroom
greenhouse field plot apartment flat
'''.split())


# After a list number, words that say themselves how the item stands to the others.
_ITEM_OPENERS = frozenset({'then', 'never', 'do', 'don', 'dont', 'avoid', 'and', 'after', 'before', 'finally',
                           'but', 'not', 'always', 'only', 'if', 'when', 'whenever', 'once', 'while', 'keep',
                           'stay', 'also', 'optionally', 'or', 'either', 'first', 'lastly', 'next', 'until'})


def bare_label(word: str) -> bool:
    """Whether a word is a letter or a short number that labels one of a kind ("island D", "gate 4")."""
    return len(word) == 1 and word.isalpha() or word.isdigit() and len(word) < 4


def is_label(word: str) -> bool:
    """Whether a word labels one of a kind: a letter, a short number or a number word ("dock three")."""
    return bare_label(word) or word in NUMBER_WORDS


def _then(number: str, following: str) -> str:
    """Return "then " for a list number after the first (a numbered list is an order), unless told."""
    return '' if number in ('0', '1', '01') or following in _ITEM_OPENERS else 'then '


_TILL_BEFORE = frozenset({'the', 'that', 'this', 'my', 'our', 'your', 'each', 'every'})
_TILL_PLACES = frozenset('''
front back main other first second third last left right middle end near far express north south east west
open
'''.split())
_TILL_AFTER = frozenset({'rolls', 'roll', 'area', 'point', 'queue', 'drawer', 'counter', 'station', 'desk',
                         'number', 'lane', 'bank', 'points'})


def _till_is_counter(before: list[str], after: list[str]) -> bool:
    """Whether "till" names a shop's counter ("the till", "to till 4", "the till rolls"), not "until".

    ``before`` holds the words read so far, ``after`` the next two.
    """
    nxt = after[0] if after else ''
    if nxt in ('you', 'i', 'we', 'they', 'he', 'she', 'it', 'the', 'after', 'then', 'told', 'further'):
        return False   # "a till you reach b": a clause follows
    if nxt in _TILL_AFTER:
        return True
    numbered = (nxt.isdigit() or nxt in _NUMBER_NAME.values()) and (len(after) < 2 or after[1] not in (
        'o', 'oclock', 'pm', 'am', 'p', 'a', 'minutes', 'mins', 'hours', 'seconds', 'tonight', 'today'))
    prev = before[-1] if before else ''
    if prev in _TILL_PLACES and before[-2:-1] and before[-2] in _TILL_BEFORE and (
            not nxt or nxt in (',', '.', ';', '!', '?', 'or', 'and', 'then')):
        return True   # "the front till or the back till": which counter
    return prev in _TILL_BEFORE or numbered and prev not in ('until', 'not', 'wait')


def tokenize(text: str) -> list[str]:
    """Normalise an instruction and split it into word and punctuation tokens.

    Parameters
    ----------
    text:
        The instruction as typed.

    Returns
    -------
    list[str]
        Lower-case tokens; runs of the same punctuation collapse to one, a dash
        between spaces becomes a comma, and typos in :data:`TYPOS` are fixed.
    """
    if 'E' in text:   # "A and E", "A&E": the accident and emergency department, one name
        text = _A_AND_E_RE.sub(r'\1a_and_e', text)
    acronyms: set[int] = set()
    if not text.islower():   # each of these is said in capitals ("the IT office", "field A", "shelf B4")
        acronyms = {m.start(2) for m in _ACRONYM_RE.finditer(text) if m.group(2).isupper()}
        acronyms |= {m.start(1) for m in _ITEM_ACRONYM_RE.finditer(text)}
        acronyms |= {m.start(1) for m in _LETTER_RE.finditer(text)}
        acronyms |= {m.start() for m in _B4_RE.finditer(text)}
    if acronyms:
        # marked so that lower-casing keeps them apart from the words they spell ("it", "or")
        text = ''.join(f'zq{c.lower()}' if i in acronyms else c for i, c in enumerate(text))
    s = text.lower().replace('\u2019', "'").replace('\u2018', "'").replace('`', "'")
    if not s.isascii():   # "the café", "the Fabergé eggs": the letters without their accents
        s = ''.join(c for c in unicodedata.normalize('NFKD', s) if not unicodedata.combining(c))
    # a list written as lines or bullets: each line, "1)", "(2)", "3." or bullet opens a clause
    # (a numbered list is an order: each number after the first reads as "then")
    s = re.sub(r'(^|[\s:;,])\(?(\d{1,2})\)(?=\s+([a-z]*))',
               lambda m: f'{m.group(1)} , {_then(m.group(2), m.group(3))}', s)
    s = re.sub(r'(^|[:;,.!?\n]\s*)(\d{1,2})\.(?=\s+([a-z]*))',
               lambda m: f'{m.group(1)} , {_then(m.group(2), m.group(3))}', s)
    s = re.sub(r'(^|\n)\s*[-*\u2022\u25cf\u25aa]+\s', r'\1 , ', s)
    s = re.sub(r'(?<![.;:!?,\s])[ \t]*\n', ' . ', s)
    s = re.sub(r'[\u2022\u25cf\u25aa]', ' , ', s)
    if '>' in s or '\u2192' in s:   # "the lobby > mail room > loading dock", "a -> b": an order
        s = re.sub(r'(?<=[a-z0-9)])\s*(?:-{1,2}>|={1,2}>|>|\u2192)\s*(?=[a-z0-9(])', ' then ', s)
    s = re.sub(r'\s[-\u2013\u2014]+\s|\.\.\.+|\u2026', ' , ', s)
    if '/' in s or '&' in s or '+' in s:
        # chat shorthand ("w/e you find first", "w/o"), a slash between spaces separates list items
        # ("mail room / supply closet"), and "&" or "+" between words is "and" ("lost & found")
        s = _SLASH_SHORT_RE.sub(lambda m: _SLASH_SHORT[m.group(0)], s)
        s = re.sub(r'(?<=[a-z0-9]) / (?=[a-z0-9])', ' , ', s)
        s = re.sub(r'(?<=[a-z0-9]) [&+] (?=[a-z0-9])', ' and ', s)
    if '.' in s:   # "Mr. Alvarez": the title's full stop ends no sentence
        s = re.sub(r'\b(mr|mrs|ms|dr)\.(?= [a-z])', r'\1', s)
    s = re.sub(r'\b(\d{1,2}) ?x\b', r'\1 times', s)   # "swing by the desk 2x"
    if 'min' in s:   # "for a min", "in 5 mins": the time unit spelled out ("a sec" is read as it is)
        s = re.sub(r'\b(a|one|\d{1,2}|few|couple|couple of|two|three|five|ten) mins?\b',
                   lambda m: f'{m.group(1)} minute' + ('' if m.group(1) in ('a', 'one', '1') else 's'), s)
    for pattern, repl in CONTRACTIONS:
        s = re.sub(pattern, repl, s)
    if 'its ' in s:   # "bring its charger": after a verb or preposition "its" is no "it is"
        s = re.sub(r'\b(bring|take|carry|move|put|grab|get|fetch|return|to|on|in|at|by|near|from|of|with|'
                   r'under|behind|beside) its\b', r'\1 the', s)
    if '-' in s:   # "the walk-in cooler", "the drop-off point": one word of a name
        s = _PARTICLE_COMPOUND_RE.sub(lambda m: '_'.join(g for g in m.groups() if g), s)
    if 'the ' in s:   # "the walk-in", "the walkin", "the dropoff"
        s = _NOUN_COMPOUND_RE.sub(lambda m: m.group(1) + ' ' + '_'.join(g for g in m.groups()[1:] if g), s)
    s = re.sub(r'(?<=[a-z])-(?=[a-z])', ' ', s)
    if 'ur ' in s:   # "on ur way": "ur" before a noun is "your", elsewhere "you are"
        s = re.sub(r'\bur (?=(?:way|own|turn|time|choice|call|left|right|route|path|trip|return|best|'
                   r'hand|hands|grip|gripper|arm|arms|charger|dock|battery|sensors|camera|base|spot|station|'
                   r'charging)\b)',
                   'your ', s)
    if re.search(r'(?:to|at|into|outside|from) \d{3}\b', s):   # "go up to 204": room 204
        s = re.sub(r'\b(to|at|into|outside|from) (\d{3})\b(?! ?(?:times|meters|metres|m|cm|feet|ft|percent|%|'
                   r'degrees|am|pm|hours|minutes|seconds|kg|km|miles)\b)', r'\1 room \2', s)
    if ' 2 ' in s:   # "go 2 the break room", "the towels 2 the cart": chat spelling of "to" before a place
        # (not after a place told apart by its number: "only go in bay 2 the once")
        s = re.sub(r'\b(?P<w>[a-z]+) 2 (?=(?:the|my|our|your|this|that|either|both)\b)',
                   lambda m: m.group(0) if m.group('w') in LABEL_HEADS else f'{m.group("w")} to ', s)
        s = re.sub(r'\b(go|head|come|get|walk|drive|fly|run|move|back|over|down|up|way|next|close) 2 '
                   r'(?=(?:a|an)\b)', r'\1 to ', s)
    if ' need' in s:   # "the barn and the trough need checking", "... need a visit": check them
        s = re.sub(r'(?:\bboth )?\b((?:the|my|your|our) [^,.;:!?]+?) (?:need|needs) (?:checking|checked|'
                   r'a check|inspecting|inspected|a look|looking at|a visit|visiting)\b', r'check \1', s)
    if 'lost and found' in s:   # one place, not two
        s = s.replace('lost and found', 'lost_and_found')
    if ' drop' in s:   # "the book drop", "the key drop box": a place, no verb
        s = re.sub(r'\b(the|a|my|our|your) (book|mail|key|parcel|package|night|returns?|letter|donation) '
                   r'drop\b', r'\1 \2_drop', s)
    s = re.sub(r'\b(first|last|other|next) ([2-9])\b(?! ?(?:m|cm|meters|metres|feet|ft)\b)',
               lambda m: f'{m.group(1)} {_NUMBER_NAME[int(m.group(2))]}', s)   # "the last 2"
    if 'pair of ' in s:   # "a pair of gloves": the gloves
        s = re.sub(r'\b(a|the|my|your|our|that|this) pair of (?=[a-z])', r'\1 ', s)
    if ' of the ' in s:   # "stay of the wet floor": off
        s = re.sub(r'\b(stay|keep|get) of (?=the )', r'\1 off ', s)
    if ' form ' in s:
        s = _FORM_RE.sub(r'\1 from', s)
    if ' w' in s:
        s = _WAY_RE.sub(r'\1way', s)
    if 'their' in s:   # "go over their": "their" ends no phrase, "there" does (a homophone)
        s = re.sub(r'\b(over|in|out|up|down|back|go|get|stay|wait|it|them) their'
                   r'(?=\s*(?:[,.;:!?]|$|and\b|then\b|please\b|now\b|first\b))', r'\1 there', s)
    if 'at lease ' in s:   # "at lease twice": speech recognition's "at least"
        s = re.sub(r'\bat lease (?=once|twice|thrice|\w+ times)', 'at least ', s)
    if re.search(r'\d+s ', s):   # "bay 4s fine": "bay 4's fine", the apostrophe lost (a label is no plural)
        s = re.sub(r'\b(\d+)s (?=(?:fine|ok|okay|alright|safe|open|closed|shut|clear|free|busy|empty|full|'
                   r'locked|off limits|out of bounds|not|no)\b)', r'\1 is ', s)
    if 'forth ' in s:   # "the forth floor": the fourth
        s = re.sub(r'\bforth (?=floor|time|stop|room|door|one|place|aisle|bay|shelf|level|row)', 'fourth ', s)
    out: list[str] = []
    found = _TOKEN_RE.findall(s)
    for k, tok in enumerate(found):
        if acronyms and tok.startswith('zq'):
            out.append(tok[2:] if tok == 'zqb4' else tok[2:].upper())   # "shelf B4": shelf_b4
            continue
        if tok == 'b4' and out and out[-1] in _B4_LABELLED:
            out.append(tok)   # "bay b4", "shelf b4": a label, not "before"
            continue
        tok = ORDINAL_DIGITS.get(tok, tok)
        if tok == 'till' and _till_is_counter(out, found[k + 1:k + 3]):
            out.append(tok)   # "stuck at the till", "go to till 4": the counter, not "until"
            continue
        words = TYPOS.get(tok, tok).split()
        for w in words:
            if w in PUNCT and out and out[-1] in PUNCT:
                if w in '.;!?' and out[-1] == ',':
                    out[-1] = w
                continue
            out.append(w)
    while out and out[0] in PUNCT:
        out.pop(0)
    return out


_LABEL_RE = re.compile(r'^(?:[a-z]|[a-z]?\d{1,3}[a-z]?)$')   # "A", "3", "a1"; or a number word:
_NUMBER_LABELS = frozenset(_NUMBER_NAME.values())


# Words a number follows that are no names: counts and measures ("twice three times four times").
_NOT_LABELLED = frozenset({'times', 'time', 'minutes', 'minute', 'seconds', 'hours', 'metres', 'meters',
                           'feet', 'laps', 'passes', 'rounds', 'visits', 'trips', 'x', 'by', 'and', 'or',
                           'to', 'of'})


def separate_labels(tokens: list[str]) -> list[str]:
    """Set labelled names said one after another apart: "bay 1 bay 2 and bay 3" -> "bay 1 , bay 2 and bay 3".

    Speech comes without commas; a number followed by the words said before it starts a new name
    (one kind, told apart by the number), never a longer name ("bed 2 bed 4" is no bed_2_bed_4).
    """
    out: list[str] = []
    for k, t in enumerate(tokens):
        out.append(t)
        if (t.isdigit() or t in _NUMBER_LABELS) and 0 < k < len(tokens) - 1 and \
                tokens[k - 1] not in _NOT_LABELLED and any(
                    k >= n and tokens[k + 1:k + 1 + n] == tokens[k - n:k] and tokens[k - n] not in PUNCT
                    for n in (1, 2, 3)):
            out.append(',')
    return out


def expand_labels(tokens: list[str]) -> list[str]:
    """Name each labelled thing of a list in full: "turbines A, B and C" -> "turbine A, turbine B, ...".

    Labels are single letters or short numbers ("gates A1, A2 and A3"), after a plural noun,
    listed with commas and a last "and" or "or"; a later "the middle one" then means turbine B.
    """
    out: list[str] = []
    i = 0
    while i < len(tokens):
        t = tokens[i]
        labels: list[int] = []
        if len(t) > 3 and t.endswith('s') and t.isalpha() and i + 1 < len(tokens):
            j = i + 1
            while j < len(tokens) and (_LABEL_RE.match(tokens[j].lower()) or tokens[j] in _NUMBER_LABELS):
                labels.append(j)
                if j + 1 < len(tokens) and tokens[j + 1] in (',', 'and', 'or'):
                    j += 2 if tokens[j + 1] != ',' or tokens[j + 2:j + 3] not in (['and'], ['or']) else 3
                else:
                    break
        # ... or three or more with commas only, the list ended by punctuation ("conf rms A, B, C - ...")
        if len(labels) >= 2 and any(tokens[m - 1] in ('and', 'or') for m in labels[1:]) or \
                len(labels) >= 3 and (labels[-1] + 1 == len(tokens) or tokens[labels[-1] + 1] in PUNCT):
            noun = t[:-2] if t.endswith(('ches', 'shes', 'xes', 'sses')) else \
                t[:-3] + 'y' if t.endswith('ies') and len(t) > 4 else t[:-1]   # "galleries 14 and 15"
            end = labels[-1] + 1
            for k in range(i + 1, end):
                out.extend([noun, tokens[k]] if k in labels else [tokens[k]])
            i = end
            continue
        out.append(t)
        i += 1
    return out
