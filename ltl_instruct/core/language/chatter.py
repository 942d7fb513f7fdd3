"""Chatter: the words around an instruction that ask for nothing, and how to tell them apart.

People frame instructions ("Hi! We've got visitors coming, so..."), add courtesy and
time words ("for me", "real quick", "this evening"), and describe the scene ("the cat
keeps knocking things off the counter"). None of it names a goal, a constraint or an
order, so the offline translator may leave it out, but never silently: every part
left out is named in the translation's notes, which the verification dialog shows the
person before the robot moves.

What may be left out is decided by what the words lack, not by a list of sentences:

- a *statement* (:func:`is_statement`): a clause whose subject is not the robot ("I
  left...", "we have got...", "the sprinkler is off") and that carries no constraint
  word; the things it names stay known for "it" and "there";
- *filler* (:func:`is_filler`): words with no place, no skill verb and no constraint
  word in them ("be careful", "for me", "just so you know");
- *courtesy and time phrases* at the end of a clause, and lead-ins such as "just so you
  know," at its start (:func:`strip_courtesy`).

Words that could carry meaning (a negation, an order or time word, a count, a
place) are never left out: the translator still raises ``TranslationError`` on them.
"""
from __future__ import annotations

import re
from typing import Sequence

from ltl_instruct.core.language.phrases import (
    DETERMINERS, NUMBER_SUBJECT_VERBS, PLACEHOLDER_ADJECTIVES, STOPWORDS, is_name_word, match_relation,
)
from ltl_instruct.core.language.text import FAMILY_NAMES, NUMBER_WORDS, ORDINALS, PUNCT

# Words that change what the robot must do; a part holding one is never left out.
CONSTRAINT_WORDS = frozenset('''
limits bounds forbidden prohibited banned dangerous unsafe hazardous restricted
not never no avoid avoiding away without except unless before after until till then first last
once twice thrice times time only always whenever while when if either or nor again more less least
most exactly stay keep leave instead but forbidden mustn cannot nothing none neither
'''.split()) | frozenset(NUMBER_WORDS) | frozenset(ORDINALS)

# Subjects that make a clause a statement about the world, not a request to the robot.
STATEMENT_SUBJECTS = frozenset({'i', 'we', 'they', 'he', 'she', 'it', 'this', 'that', 'someone',
                                'somebody', 'everyone', 'nobody', 'people'})
# After such a subject, words that turn the clause into a request after all.
REQUEST_WORDS = frozenset({'need', 'want', 'would', 'like', 'should', 'must', 'will', 'can', 'could',
                           'mean', 'meant', 'am', 'wanted', 'needed', 'asked', 'ask', 'expect',
                           'prefer', 'wish', 'hope', 'd', 'shall', 'may', 'might', 'ought', 'to', 'you'})
# Finite verbs after a noun-phrase subject ("the cat keeps...", "the gate is...").
FINITE_VERBS = frozenset('''
upsets works usually
is are was were keeps keep has had seems seem looks look sits sit stands lies lie got gets needs
belongs goes went broke fell spilled leaks leaked smells tends happens arrive arrives arrived came comes
dropped jammed stopped started moved died spilt broken overflowed overflows ran runs get sticks jams
bites barks sleeps wobbles squeaks creaks
live lives curls hide hides play plays nest nests
'''.split())

# How a thing is ("the floor is wet"): after "is" a description of the scene, not a request.
STATES = frozenset('''
wet slippery locked closed shut broken blocked busy occupied dirty flooded icy muddy packed crowded full
empty hot cold dark noisy fragile jammed open cracked leaking damaged sticky faulty waxed mopped nervous sick
unwell asleep loose wobbly smashed split setting drying dead low flat
'''.split())
# Words that may come between "is" and the state ("the battery is almost dead").
DEGREE_WORDS = frozenset({'almost', 'nearly', 'very', 'really', 'so', 'too', 'still', 'completely', 'totally',
                          'pretty', 'quite', 'super', 'kind', 'getting'})

# After "it is": words that make the clause a permission or a demand.
PERMISSIVE = frozenset({'okay', 'ok', 'fine', 'alright', 'allowed', 'important', 'necessary', 'essential',
                        'vital', 'crucial', 'required', 'best', 'better', 'safe', 'forbidden', 'not',
                        'mandatory'})

INTERJECTIONS = frozenset('''
hi hello hey hiya howdy thanks thank cheers great cool awesome perfect ok okay alright right sure mmm mm
please good morning afternoon evening ah oh ahh hmm um uh er erm yo dear buddy pal friend there lot
much appreciated wonderful brilliant
'''.split())
# Clause openings that wish or greet and ask for nothing ("hope you're well", "have a good one").
WISHES: tuple[tuple[str, ...], ...] = (
    ('hope',), ('i', 'hope'), ('hoping',), ('have', 'a', 'good'), ('have', 'a', 'nice'), ('good', 'luck'),
    ('be', 'careful'), ('be', 'quick'), ('be', 'gentle'), ('be', 'quiet'), ('be', 'safe'), ('take', 'care'),
    ('thanks', 'for'), ('thank', 'you', 'for'), ('sorry', 'to', 'bother'), ('sorry', 'for'),
    # how to behave, no place ("visitors are in today, so please behave")
    ('behave',), ('be', 'good'), ('be', 'polite'), ('be', 'nice'), ('be', 'on', 'your', 'best'),
    ('mind', 'your', 'manners'),
)

# How long to stay ("hover there for a few minutes"): the formula has no clock.
_DURATIONS: tuple[tuple[str, ...], ...] = tuple(
    ('for',) + amount + (unit,)
    for amount in (('a', 'few'), ('a', 'couple', 'of'), ('some',), ('two',), ('three',), ('five',), ('ten',),
                   ('a', 'few', 'more'))
    for unit in ('minutes', 'seconds', 'moments', 'mins', 'secs', 'hours')) + (
    ('for', 'a', 'while'), ('for', 'a', 'little', 'while'), ('for', 'a', 'short', 'while'),
    ('for', 'a', 'bit'), ('for', 'a', 'little', 'bit'), ('for', 'a', 'minute'), ('for', 'a', 'moment'),
    ('for', 'a', 'second'), ('for', 'a', 'sec'), ('for', 'an', 'hour'),
    ('for', 'half', 'an', 'hour')) + tuple(
    (prep, 'the', 'next') + unit for prep in ('over', 'in', 'during', 'within')
    for unit in (('hour',), ('few', 'hours'), ('couple', 'of', 'hours'), ('half', 'hour'), ('day',),
                 ('few', 'minutes'), ('ten', 'minutes'), ('twenty', 'minutes'), ('thirty', 'minutes')))
# When in the day ("over the course of the night shift").
_SPANS: tuple[tuple[str, ...], ...] = tuple(
    ('over', 'the', 'course', 'of', 'the') + span
    for span in (('day',), ('night',), ('evening',), ('morning',), ('afternoon',), ('week',), ('shift',),
                 ('night', 'shift'), ('day', 'shift'), ('late', 'shift'), ('early', 'shift'))) + tuple(
    ('during', 'the') + span
    for span in (('night', 'shift'), ('day', 'shift'), ('night',), ('day',), ('shift',))) + tuple(
    ('over', 'the') + span for span in (('morning',), ('afternoon',), ('evening',), ('day',), ('week',)))
# What the visit is for ("fly to the pylon for an inspection"): the visit itself is the task.
_PURPOSES: tuple[tuple[str, ...], ...] = tuple(
    ('for',) + art + quick + (what,)
    for art in (('a',), ('an',)) for quick in ((), ('quick',), ('closer',))
    for what in ('inspection', 'check', 'look', 'photo', 'picture', 'survey', 'scan', 'reading', 'visual',
                 'checkup', 'peek', 'glance', 'sweep'))

# Until the person signals ("wait there until I call you"): the person's event, no place to wait for.
_SIGNALS: tuple[tuple[str, ...], ...] = tuple(
    (until, who) + signal
    for until in ('until', 'till') for who in ('i', 'we')
    for signal in (('call',), ('call', 'you'), ('call', 'for', 'you'), ('ring',), ('ring', 'you'),
                   ('text', 'you'), ('ping', 'you'), ('message', 'you'), ('shout',),
                   ('give', 'you', 'a', 'shout'), ('tell', 'you'), ('say', 'so'), ('send', 'for', 'you'),
                   ('need', 'you'))) + (
    # until someone says otherwise: how long to stay, no event
    ('until', 'further', 'notice'), ('till', 'further', 'notice'), ('until', 'told', 'otherwise'),
    ('until', 'you', 'are', 'told', 'otherwise'), ('until', 'i', 'say', 'otherwise'),
    ('until', 'you', 'hear', 'otherwise'))

# Courtesy and time-of-day phrases that end a clause and ask for nothing.
COURTESY: tuple[tuple[str, ...], ...] = tuple(sorted((
    ('for', 'me'), ('for', 'us'), ('real', 'quick'), ('quick',), ('asap',), ('as', 'soon', 'as', 'possible'),
    # formal haste and timing ("Proceed to X without delay, please", "At this time, I would like you to ...")
    ('without', 'delay'), ('without', 'further', 'delay'), ('at', 'this', 'time'),
    ('at', 'your', 'earliest', 'convenience'),
    ('if', 'you', 'can'), ('if', 'you', 'could'), ('if', 'possible'), ('if', 'you', 'would'),
    ('when', 'you', 'get', 'a', 'chance'), ('when', 'you', 'can'), ('when', 'you', 'have', 'a', 'moment'),
    ('this', 'evening'), ('this', 'morning'), ('this', 'afternoon'), ('tonight',), ('today',),
    ('this', 'time'),
    ('right', 'now'), ('now',), ('thanks',), ('thank', 'you'), ('would', 'you'), ('could', 'you'),
    ('for', 'a', 'sec'), ('for', 'a', 'second'), ('please',), ('nice', 'and', 'slow'),
    ('nice', 'and', 'easy'), ('nice', 'and', 'steady'), ('slow', 'and', 'steady'), ('nice', 'and', 'slowly'),
    ('nice', 'and', 'gently'),
    ('if', 'you', 'do', 'not', 'mind'),
    ('when', 'you', 'are', 'free'), ('at', 'some', 'point', 'today'),
    ('for', 'now'), ('will', 'you'), ('okay',), ('ok',), ('cheers',), ('if', 'you', 'like'),
    ('if', 'you', 'want'), ('if', 'you', 'wish'), ('if', 'you', 'feel', 'like', 'it'), ('real', 'fast'),
    ('super', 'quick'), ('super', 'fast'), ('fast',), ('no', 'rush'), ('no', 'hurry'), ('no', 'worries'),
    ('no', 'matter', 'what'), ('thanks', 'a', 'lot'), ('thanks', 'so', 'much'),
    ('thank', 'you', 'so', 'much'), ('as', 'quick', 'as', 'you', 'can'),
    ('as', 'quickly', 'as', 'you', 'can'),
    ('as', 'fast', 'as', 'you', 'can'), ('as', 'quickly', 'as', 'possible'), ('as', 'fast', 'as', 'possible'),
    ('thank', 'you', 'ever', 'so', 'much'), ('thanks', 'ever', 'so', 'much'), ('quick', 'as', 'you', 'can'),
    ('fast', 'as', 'you', 'can'), ('quickly', 'as', 'you', 'can'), ('soon', 'as', 'you', 'can'),
    ('quick', 'as', 'possible'), ('fast', 'as', 'possible'), ('soon', 'as', 'possible'),
    ('if', 'you', 'please'), ('i', 'would', 'be', 'much', 'obliged'), ('i', 'would', 'be', 'grateful'),
    ('much', 'obliged'), ('though',), ('anyway',), ('anyways',), ('that', 'is', 'where', 'i', 'need', 'you'),
    ('that', 'is', 'where', 'i', 'want', 'you'), ('that', 'is', 'where', 'you', 'need', 'to', 'go'),
    ('and', 'take', 'a', 'look'), ('and', 'have', 'a', 'look'), ('and', 'wait'), ('and', 'wait', 'there'),
    ('many', 'thanks'), ('when', 'you', 'are', 'ready'), ('whenever', 'you', 'are', 'ready'),
    ('in', 'a', 'minute'), ('straight', 'away'), ('under', 'any', 'circumstances'), ('whatever', 'happens'),
    ('first', 'thing'), ('first', 'thing', 'tomorrow'), ('first', 'thing', 'in', 'the', 'morning'),
    ('tomorrow',), ('tomorrow', 'morning'), ('tomorrow', 'evening'), ('already',), ('anyway',), ('pronto',),
    ('sharpish',), ('smartish',), ('quick', 'smart'), ('double', 'quick'), ('chop', 'chop'),
    ('and', 'stuff'), ('or', 'something'), ('or', 'whatever'), ('if', 'that', 'is', 'ok'),
    ('if', 'that', 'is', 'okay'), ('if', 'that', 'is', 'alright'), ('if', 'that', 'is', 'fine'),
    ('if', 'you', 'would', 'be', 'so', 'kind'), ('if', 'it', 'is', 'not', 'too', 'much', 'trouble'),
    ('on', 'your', 'way', 'out'), ('on', 'the', 'way', 'out'), ('and', 'back'), ('and', 'back', 'again'),
    ('there', 'and', 'back'),
    # where a thing roughly is ("the bins round the back"): no place of its own
    ('round', 'the', 'back'), ('around', 'the', 'back'), ('round', 'the', 'front'),
    ('around', 'the', 'front'), ('out', 'the', 'back'), ('out', 'back'), ('out', 'front'),
    ('round', 'the', 'side'), ('right', 'away'), ('at', 'once'), ('as', 'fast', 'as', 'you', 'can'),
    ('as', 'quickly', 'as', 'you', 'can'), ('as', 'soon', 'as', 'you', 'can'),
    ('as', 'quickly', 'as', 'possible'), ('as', 'fast', 'as', 'possible'),
    ('when', 'you', 'get', 'a', 'sec'), ('when', 'you', 'get', 'a', 'second'),
    ('when', 'you', 'get', 'a', 'minute'),
    ('when', 'you', 'get', 'a', 'moment'), ('when', 'you', 'get', 'the', 'chance'),
    ('when', 'you', 'have', 'a', 'sec'),
    ('when', 'you', 'have', 'a', 'second'), ('when', 'you', 'have', 'a', 'minute'),
    ('when', 'you', 'have', 'time'),
    ('when', 'you', 'have', 'a', 'chance'), ('whenever', 'you', 'can'),
    ('whenever', 'you', 'get', 'a', 'chance'),
    ('whenever', 'you', 'get', 'the', 'chance'), ('if', 'you', 'get', 'a', 'chance'),
    ('if', 'you', 'have', 'time'),
    ('at', 'your', 'convenience'), ('when', 'convenient'), ('when', 'it', 'is', 'convenient'),
    ('in', 'a', 'bit'),
    ('later', 'today'), ('later', 'on'), ('when', 'you', 'get', 'around', 'to', 'it'), ('soon',),
    ('for', 'a', 'bit'), ('a', 'bit'),
    ('for', 'a', 'minute'), ('for', 'a', 'moment'), ('if', 'you', 'would', 'not', 'mind'),
    ('thanks', 'in', 'advance'),
    ('if', 'you', 'please'), ('when', 'you', 'are', 'able'), ('whenever', 'you', 'are', 'free'),
    ('in', 'a', 'sec'), ('in', 'a', 'second'), ('while', 'you', 'are', 'at', 'it'),
    ('while', 'you', 'are', 'there'), ('no', 'rush', 'at', 'all'), ('no', 'hurry', 'at', 'all'),
    ('this', 'shift'), ('this', 'week'), ('per', 'shift'), ('each', 'shift'), ('a', 'shift'), ('per', 'day'),
    ('per', 'night'), ('for', 'the', 'afternoon'), ('for', 'the', 'morning'),
    ('for', 'the', 'evening'), ('for', 'the', 'day'), ('full', 'stop'), ('on', 'the', 'double'),
    ('when', 'you', 'have', 'got', 'a', 'sec'), ('when', 'you', 'have', 'got', 'a', 'second'),
    ('when', 'you', 'have', 'got', 'a', 'minute'), ('when', 'you', 'have', 'got', 'a', 'moment'),
    ('and', 'hang', 'about'), ('and', 'hang', 'around'), ('till', 'i', 'come'),
    ('until', 'i', 'come', 'back'),
    ('while', 'i', 'am', 'out'), ('while', 'i', 'am', 'away'), ('while', 'we', 'are', 'out'),
    ('all', 'night'),
    ('all', 'day'), ('before', 'morning'), ('by', 'morning'),
    ('until', 'i', 'am', 'back', 'from', 'my', 'call'), ('and', 'wait', 'for', 'me', 'there'),
    ('wait', 'for', 'me', 'there'), ('to', 'land'), ('and', 'land'), ('until', 'i', 'get', 'there'),
    ('until', 'i', 'arrive'), ('until', 'i', 'come'), ('until', 'i', 'am', 'back'),
    ('till', 'i', 'get', 'there'), ('until', 'we', 'get', 'there'), ('for', 'the', 'next', 'job'),
    ('and', 'hold', 'position'), ('and', 'hold', 'there'), ('and', 'wait', 'for', 'the', 'next', 'job'),
    ('with', 'the', 'drone'), ('with', 'the', 'robot'), ('using', 'the', 'drone'), ('whatever', 'you', 'do'),
    ('before', 'bedtime'), ('before', 'bed'), ('before', 'close'), ('before', 'closing'), ('before', 'lunch'),
    ('before', 'dinner'), ('before', 'we', 'close'), ('before', 'we', 'open'),
    ('before', 'the', 'shop', 'opens'),
    ('before', 'the', 'store', 'opens'), ('before', 'opening'), ('before', 'dark'), ('over', 'the', 'night'),
    ('straight', 'after'), ('right', 'after'), ('for', 'the', 'rest', 'of', 'the', 'shift'),
    ('for', 'the', 'rest', 'of', 'the', 'night'), ('for', 'the', 'rest', 'of', 'the', 'day'),
    ('from', 'the', 'air'), ('right', 'now', 'please'),
    # the service or the session the request is for ("exactly twice this service")
    ('this', 'service'), ('during', 'service'), ('tonight', 'at', 'service'), ('this', 'session'),
) + _DURATIONS + _SPANS + _PURPOSES + _SIGNALS,
    key=lambda t: -len(t)))
_CLAUSE_END = frozenset({'and', 'then', 'but', 'so'}) | PUNCT
# Words that start what something is done for ("... please, to check the gate", "Just to check ...:").
_WHAT_FOR = (['to', 'check'], ['to', 'make'], ['to', 'see'])
# Times of the day a list of tasks is to be done by ("couple of things before first period:").
_TIMES_OF_DAY = frozenset('''
lunch lunchtime dinner breakfast noon midday period class school assembly closing opening bedtime tonight
tomorrow break recess service shift dark
'''.split())
# Lead-ins that ask for nothing only at the very start (later they take back what came before).
# A pause asked for before anything is said ("hang on, can you just go to ...") corrects nothing.
START_LEADS: tuple[tuple[str, ...], ...] = (
    ('never', 'mind'), ('nevermind',), ('forget', 'it'), ('hang', 'on'), ('hold', 'on'),
    ('hang', 'on', 'a', 'sec'), ('hold', 'on', 'a', 'sec'), ('hang', 'on', 'a', 'second'),
    ('hold', 'on', 'a', 'second'),
    ('wait', 'a', 'sec'), ('wait', 'a', 'second'), ('one', 'sec'), ('one', 'second'), ('just', 'a', 'sec'),
    ('just', 'a', 'second'))
# Lead-ins before a comma that announce what follows and ask for nothing themselves.
LEADS: tuple[tuple[str, ...], ...] = tuple(sorted((
    ('before', 'the', 'end', 'of', 'lunch'), ('before', 'lunch'),
    ('before', 'the', 'end', 'of', 'the', 'day'),
    ('by', 'the', 'end', 'of', 'the', 'day'), ('before', 'the', 'end', 'of', 'the', 'shift'),
    ('fyi',), ('just', 'so', 'you', 'know'), ('busy', 'morning'), ('busy', 'day'), ('long', 'day'),
    ('busy', 'afternoon'), ('hectic', 'morning'), ('crazy', 'day'), ('busy', 'night'), ('so', 'you', 'know'),
    ('by', 'the', 'way'), ('btw',), ('at', 'this', 'time'), ('at', 'this', 'point'), ('at', 'present'),
    ('however',),
    ('heads', 'up'), ('just', 'a', 'heads', 'up'), ('for', 'your', 'information'), ('as', 'you', 'know'),
    ('listen',), ('look',), ('hey', 'there'), ('quick', 'one'), ('quick', 'favour'), ('quick', 'favor'),
    ('one', 'more', 'thing'), ('oh', 'and'), ('also', 'fyi'), ('for', 'the', 'record'), ('well',),
    ('no', 'rush'), ('no', 'hurry'), ('no', 'worries'), ('no', 'pressure'), ('no', 'problem'),
    ('whenever', 'you', 'are', 'ready'), ('when', 'you', 'are', 'ready'), ('once', 'you', 'are', 'ready'),
    ('if', 'you', 'are', 'ready'), ('when', 'you', 'get', 'a', 'chance'), ('when', 'you', 'can'),
    ('if', 'you', 'can'), ('if', 'possible'), ('if', 'you', 'do', 'not', 'mind'), ('in', 'a', 'minute'),
    ('right',), ('alright', 'then'), ('okay', 'then'), ('ok', 'then'), ('now', 'then'),
    ('when', 'you', 'have', 'a', 'moment'), ('when', 'you', 'have', 'a', 'minute'),
    ('when', 'you', 'have', 'a', 'sec'),
    ('when', 'you', 'have', 'a', 'second'), ('when', 'you', 'have', 'time'),
    ('when', 'you', 'have', 'a', 'chance'),
    ('when', 'you', 'get', 'a', 'moment'), ('when', 'you', 'get', 'a', 'minute'),
    ('when', 'you', 'get', 'a', 'sec'),
    ('when', 'you', 'get', 'the', 'chance'), ('whenever', 'you', 'can'),
    ('whenever', 'you', 'get', 'a', 'chance'),
    ('if', 'you', 'have', 'a', 'moment'), ('if', 'you', 'have', 'a', 'minute'), ('if', 'you', 'have', 'time'),
    ('if', 'you', 'get', 'a', 'chance'), ('when', 'you', 'are', 'free'), ('whenever', 'you', 'are', 'free'),
    ('at', 'your', 'convenience'), ('when', 'convenient'), ('first', 'of', 'all'), ('to', 'start'),
    ('to', 'begin'), ('to', 'begin', 'with'), ('for', 'starters'), ('okay', 'so'), ('ok', 'so'), ('so',),
    ('alright', 'so'), ('right', 'so'), ('hey', 'robot'), ('hi', 'robot'), ('robot',), ('drone',),
    ('mister', 'robot'), ('mr', 'robot'), ('dear', 'robot'), ('okay', 'robot'), ('hey', 'drone'),
    ('mister', 'drone'), ('mr', 'drone'),
    ('before', 'anything', 'else'), ('first', 'things', 'first'), ('before', 'you', 'do', 'anything', 'else'),
    ('to', 'start', 'with'), ('to', 'start', 'off'), ('for', 'a', 'start'),
    # a drone's take-off, which every flight starts with
    ('once', 'you', 'are', 'airborne'), ('once', 'airborne'), ('when', 'you', 'are', 'airborne'),
    ('once', 'you', 'are', 'in', 'the', 'air'), ('once', 'you', 'are', 'up'),
    ('once', 'you', 'have', 'taken', 'off'), ('after', 'taking', 'off'), ('after', 'take', 'off'),
    ('after', 'takeoff'), ('after', 'you', 'take', 'off'), ('once', 'you', 'are', 'off', 'the', 'ground'),
    ('when', 'you', 'are', 'up'), ('once', 'in', 'the', 'air'),
), key=lambda t: -len(t)))

PREPOSITIONS = frozenset({'of', 'to', 'in', 'at', 'from', 'near', 'by', 'on', 'into', 'onto', 'through',
                          'past', 'toward', 'towards', 'inside', 'behind', 'under', 'over', 'beside',
                          'between', 'around', 'with', 'outside', 'across', 'along', 'via', 'up', 'down'})

# Things done where the robot already is ("go to the door and knock"): no goal of their own
# unless a place follows them ("clean the kitchen" is read as going there).
ACTIVITY_VERBS = frozenset('''
wash knock sit stand wait rest look listen open close shut ring check tidy clean dust sweep mop vacuum
lie kneel pause charge recharge beep watch take stay turn switch unlock lock press push pull make hang
chill relax idle linger loiter hover
'''.split()) - {'take', 'push', 'make', 'turn', 'switch', 'stay'}

# Frames around a request that ask for nothing themselves, and what they become.
FRAMES: tuple[tuple[re.Pattern[str], str], ...] = tuple((re.compile(p), r) for p, r in (
    (r'(^ | [,.;!?] )(?:honestly |so |well )?(?:the )?(?:easiest|best|simplest|quickest|ideal) '
     r'(?:thing|option|way|plan|move)(?: to do)? (?:would be|is|will be) (?:for you )?(?:to )?', r'\1 '),
    (r'(^ | [,.;!?] )(?:it is|it would be) (?:really |very |super |extremely )?(?:important|vital|crucial|'
     r'essential|critical|key|imperative) (?:that )?(?:you )?(?:to )?', r'\1 '),
    (r'(^ | [,.;!?] )(?:it would be|it is|it will be|that would be) (?:great|nice|good|lovely|helpful|'
     r'awesome|ideal|perfect|wonderful) if you (?:could|would|can|will) ', r'\1 '),
    (r'(^ | [,.;!?] )(?:it is )?(?:time|high time) (?:for you )?to ', r'\1 '),
    (r'(^ | [,.;!?] )do me a (?:favour|favor) and ', r'\1 '),
    (r'(^ | [,.;!?] )(?:would|could|do|will) you mind ', r'\1 '),
    (r'(^ | [,.;!?] )(?:(?:would|could|will) you )?(?:please )?be (?:so (?:kind|good)|(?:kind|good) enough) '
     r'(?:as )?to ', r'\1 '),
    (r'(^ | [,.;!?] )whatever (?:you do|happens)(?: ,)? (?=(?:do not|never|avoid|stay|keep|steer|no) )',
     r'\1 '),
    (r'(^ | [.;!?] )(?:i|we) (?:would|will|d) (?:love|like|prefer|want) (?:for )?(?:you )?to ', r'\1 '),
    # (after a comma only with "you": "..., I'd like to do some mending" is the person's own plan)
    (r'( , )(?:i|we) (?:would|will|d) (?:love|like|prefer|want) (?:for )?you to ', r'\1 '),
    (r'(^ | [,.;!?] )(?:i|we) (?:would|will|d) (?:love|like|appreciate|prefer) it if you '
     r'(?:could|would|can|will) ',
     r'\1 '),
    # "I would ask that you stay away from X", "I must insist that you ...": a formal request
    (r'(^ | [,.;!?] )(?:i|we) (?:would |must |have to |do |will )?(?:ask|request|insist|require) '
     r'(?:that |of you that )?you (?:please )?', r'\1 '),
    (r'(^ | [,.;!?] )let (?:us )?(?=(?:go|visit|head|move|drive|fly|walk|check|bring|take|swing|stop|pop|'
     r'get) )', r'\1 '),
    (r'(^ | [,.;!?] )i am not (?:sure|certain) (?:where|if|whether|what|which|how) [^,.;!?]*(?:, )?', r'\1 '),
    (r'(^ | [,.;!?] )(?:maybe|perhaps|probably) (?=[a-z])', r'\1 '),
))


# Nouns that name a list of tasks, not a place: a heading before a colon ("Morning routine:").
TASK_NOUNS = frozenset('''
routine routines plan plans task tasks errand errands job jobs chore chores instruction instructions agenda
itinerary mission missions schedule steps step program programme todo list checklist rundown
orders assignment assignments duty duties workflow procedure protocol today tonight
morning afternoon evening plan rules rule note notes reminder reminders request requests things favours
favors jobs bits important warning caution attention heads ps nb careful update route path flightplan
stops rounds restock restocking cleanup setup refill refills resupply housekeeping maintenance
'''.split())


# Verbs that open a command, not a heading ("go to these in this order: ...").
_COMMANDS = frozenset({'go', 'visit', 'head', 'bring', 'take', 'put', 'do', 'move', 'drive', 'fly', 'walk',
                       'get', 'fetch', 'carry', 'deliver', 'survey', 'patrol', 'avoid', 'stop', 'swing'})
# A heading that changes the plan given before is a self-correction ("Change of plan: ..."), read later.
_CHANGES = frozenset({'change', 'changed', 'correction', 'update', 'updated', 'new', 'revised', 'actually',
                      'instead', 'wait', 'sorry', 'amended', 'different'})


# Sounds of hesitation, said anywhere ("the uh gate", "feed silo, uh, then"); "er" after "the" is the ER.
HESITATIONS = frozenset({'uh', 'uhh', 'uhm', 'um', 'umm', 'erm', 'er', 'hm', 'hmm', 'hmmm', 'mmm', 'mm',
                         'ehm', 'eh', 'ah', 'ahh', 'ehh', 'ehhh', 'ahhh'})


# Words after which a phrase cannot end: a pause after one is never a correction ("at the, um, ...").
_DANGLING = DETERMINERS | PREPOSITIONS | frozenset({'and', 'then', 'or', 'but', 'than', 'is', 'are', 'which'})


# Verbs that open a step of their own: a pause before one corrects nothing.
_CLAUSE_VERBS = frozenset('''
go head visit come fly drive walk then bring take put avoid stay keep return stop land move proceed swing pop
just please finally steer never do
'''.split())


def join_restarts(tokens: list[str], notes: list[str]) -> list[str]:
    """Close a pause inside a phrase: "then the, uh, the spice rack" is "then the spice rack".

    Runs before the corrections are read, where "X, uh, Y" may replace X by Y: after a word
    that cannot end a phrase (a determiner, a preposition, "then") the pause corrects nothing,
    and the word said again after it ("the, uh, the") is read once.
    """
    out: list[str] = []
    k = 0
    dropped: list[str] = []
    while k < len(tokens):
        t = tokens[k]
        if t in HESITATIONS:
            kept = out[:]
            while kept and kept[-1] == ',':
                kept.pop()
            j = k + 1
            while j < len(tokens) and (tokens[j] == ',' or tokens[j] in HESITATIONS):
                j += 1
            if kept and j < len(tokens) and tokens[j] in _CLAUSE_VERBS and kept[-1] not in PUNCT and \
                    kept[-1] not in _DANGLING and not (
                        # "the armchair or the couch, hmm, just the couch": a correction
                        tokens[j] in ('just', 'finally') and tokens[j + 1:j + 2] and
                        tokens[j + 1] in DETERMINERS):
                # "after the bookcase, um, go to the window seat": a pause before a new step, no correction
                dropped.append(t)
                out = kept + [',']
                k = j
                continue
            if kept and kept[-1] in _DANGLING and j < len(tokens) and tokens[j] not in PUNCT:
                if tokens[j] == kept[-1]:
                    j += 1   # "the, uh, the": once
                dropped += [w for w in tokens[k:j] if w != ',']
                out = kept
                k = j
                continue
        out.append(t)
        k += 1
    if dropped:
        notes.append(f'left out "{" ".join(dropped)}" (a pause inside a phrase)')
    return out


_BRING_ME = frozenset({'bring', 'get', 'fetch', 'grab', 'take'})
_WHERE_I_AM = re.compile(
    r'(?:^|(?<=[,.;!?] ))(?:(?:and|but|so) )?i am (?:(?:sitting|lying|waiting|standing|out|over|up|down) )?'
    r'(?P<p>on|at|in|by|next to|near) (?P<x>(?:the|my|our) (?:[a-z0-9_]+ ){0,3}?[a-z0-9_]+)'
    r'(?: (?:right now|now))?(?= [,.;!?]|$)')


def deliver_to_speaker(tokens: list[str], notes: list[str]) -> list[str]:
    """Deliver "bring me X" to where the person says they are ("I'm on the couch").

    Without a place for "me" the delivery ends at the pick; the place the person says they are
    at, in a clause of its own, is where "me" is.
    """
    if 'me' not in tokens or 'am' not in tokens:
        return tokens
    text = ' '.join(tokens)
    where = _WHERE_I_AM.search(text)
    if where is None:
        return tokens
    place = where.group('x').split()
    said = f'"{where.group(0).strip(" ,.")}": brought to {"_".join(place[1:])}, where you are'
    rest = (text[:where.start()] + text[where.end():]).split()
    while rest and rest[0] in PUNCT:
        rest = rest[1:]
    k = next((k for k in range(len(rest) - 1) if rest[k] in _BRING_ME and rest[k + 1] == 'me'), -1)
    if k < 0:
        # "bring the big hammer to me, I'm at the bull pen": "to me" is the place said
        v = next((v for v in range(len(rest)) if rest[v] in _BRING_ME), -1)
        m = next((m for m in range(v + 2, len(rest) - 1) if rest[m:m + 2] == ['to', 'me'] and (
            m + 2 == len(rest) or rest[m + 2] in PUNCT)), -1) if v >= 0 else -1
        if m < 0 or any(t in '.;!?' for t in rest[v:m]):
            return tokens
        notes.append(said)
        return rest[:m + 1] + place + rest[m + 2:]
    end = next((e for e in range(k + 2, len(rest)) if rest[e] in '.;!?' or rest[e] == ',' and (
        e + 1 >= len(rest) or rest[e + 1] in ('then', 'and', 'but', 'after'))), len(rest))
    if any(t in ('to', 'into', 'onto') for t in rest[k + 2:end]):
        return tokens   # "bring me the cup to the table": the place is said
    while end > k + 2 and rest[end - 1] in PUNCT:
        end -= 1
    notes.append(said)
    return rest[:k + 1] + rest[k + 2:end] + ['to'] + place + rest[end:]


def strip_hesitations(tokens: list[str], notes: list[str]) -> list[str]:
    """Drop sounds of hesitation and a word said twice in a row ("avoid the the shop"), anywhere."""
    out: list[str] = []
    dropped: list[str] = []
    twice: list[str] = []
    addressed: list[str] = []
    skip_comma = False
    for k, t in enumerate(tokens):
        before = tokens[k - 1] if k > 0 else '.'
        if addressed and k > 0 and before == addressed[-1] and not out:
            before = '.'   # "yo drone fly over X": both are said to it
        after = tokens[k + 1] if k + 1 < len(tokens) else '.'
        vocative = t in VOCATIVES and before in PUNCT and (
            after in PUNCT or before in '.;!?' and after in _COMMAND_STARTS) or \
            t == 'k' and (before in '.;!?' or after in '.;!?')   # "..., dear?", "k go to the desk"
        if t in HESITATIONS and not (t == 'er' and out and out[-1] == 'the') or vocative:
            (addressed if vocative else dropped).append(t)
            if out and out[-1] == ',' and k + 1 < len(tokens) and tokens[k + 1] in PUNCT:
                out.pop()   # "silo, uh, then": one comma stays
            skip_comma = not out or out[-1] in PUNCT   # "C. Hmm, scratch that": no comma left at the start
            continue
        if t == ',' and skip_comma:
            skip_comma = False
            continue
        skip_comma = False
        if out and t == out[-1] and t in DOUBLED:
            twice.append(t)
            continue
        out.append(t)
    if dropped:
        notes.append(f'left out "{" ".join(dropped)}" (hesitation)')
    if addressed:
        notes.append(f'left out "{" ".join(addressed)}" (a form of address)')
    if twice:
        notes.append(f'read "{" ".join(twice)}", said twice in a row, once')
    return out


# Words before a form of address that make it one phrase ("little drone", "my dear", "good robot").
_ADDRESS_ADJECTIVES = frozenset({'little', 'my', 'good', 'clever', 'dear', 'old', 'silly', 'sweet', 'young'})
# Words that may lead into a form of address at the start of a sentence ("okay little drone, ...").
_ADDRESS_LEADS = frozenset({'okay', 'ok', 'alright', 'right', 'now', 'so', 'well', 'hey', 'hi', 'hello',
                            'oi'})
# Exclamations about oneself, set off by commas ("oh, no, silly me, I meant ..."): they ask for nothing.
_SELF_EXCLAIMS: tuple[tuple[str, ...], ...] = (
    ('dear', 'oh', 'dear'), ('oh', 'my', 'goodness'), ('silly', 'me'), ('dear', 'me'), ('oh', 'dear'),
    ('bless', 'me'), ('goodness', 'me'), ('my', 'goodness'), ('oh', 'my'), ('stupid', 'me'))   # longest first


def strip_addresses(tokens: list[str], notes: list[str]) -> list[str]:
    """Drop forms of address and exclamations set off by punctuation, before corrections are read.

    "no, sorry, dear, I meant the toilet", "oh, no, silly me, I meant the nook", "Now, little
    drone, would you ...": the words between the commas address someone or exclaim and name
    nothing, so the correction marker reaches what it corrects. A single address word is also
    left to :func:`strip_hesitations`; here only a word set off on both sides, or a phrase.
    """
    if not _ADDRESS_WORDS & set(tokens):
        return tokens
    out: list[str] = []
    dropped: list[str] = []
    k = 0
    n = len(tokens)
    while k < n:
        before = out[-1] if out else '.'
        if before in PUNCT or before in _ADDRESS_LEADS and (len(out) == 1 or out[-2] in PUNCT):
            m = next((len(p) for p in _SELF_EXCLAIMS if tuple(tokens[k:k + len(p)]) == p), 0)
            if not m and tokens[k] in VOCATIVES:
                m = 1
            elif not m and tokens[k] in _ADDRESS_ADJECTIVES and tokens[k + 1:k + 2] and \
                    tokens[k + 1] in VOCATIVES:
                m = 2
            elif not m and not out and tokens[k].isalpha() and tokens[k] not in STOPWORDS:
                # "Service robot, report to ...", "Apron drone two, ...": the machine addressed by its kind
                m = next((j + 1 for j in (1, 2) if tokens[k + j:k + j + 1] and tokens[k + j] in (
                    'robot', 'drone', 'bot') and tokens[k + j + 1:k + j + 2] == [','] and all(
                        t.isalpha() and t not in STOPWORDS for t in tokens[k:k + j])), 0)
                after = tokens[k + m + 1] if k + m + 1 < n else '.'
                if m and (after in STOPWORDS and after not in _COMMAND_STARTS or after in PUNCT):
                    m = 0   # ("kitchen robot, then the hall": a list of places)
                if m:
                    dropped.append(' '.join(tokens[k:k + m]))
                    k += m + 1
                    continue
            if m and (k + m >= n or tokens[k + m] in PUNCT) and (m > 1 or out):
                dropped.append(' '.join(tokens[k:k + m]))
                k += m
                if out and out[-1] == ',' and k < n and tokens[k] in PUNCT:
                    k += tokens[k] == ','   # one comma stays: "no , sorry , i meant"
                continue
        out.append(tokens[k])
        k += 1
    if dropped:
        notes.append(f'left out "{", ".join(dropped)}" (a form of address)')
    return out


# Words a request starts with, after a name it is addressed to ("bro just go to the fridge").
_COMMAND_STARTS = frozenset({'just', 'go', 'please', 'can', 'could', 'bring', 'take', 'fly', 'come', 'grab',
                             'put', 'never', 'avoid', 'stay', 'visit', 'head', 'hit', 'now', 'robot',
                             'drone'})
# Ways of addressing the person or the robot, set off by commas ("Dear, would you ...").
VOCATIVES = frozenset({'dear', 'honey', 'sweetie', 'buddy', 'pal', 'mate', 'love', 'sir', 'madam', 'maam',
                       'robot', 'drone', 'bot', 'friend', 'darling', 'hun', 'bro', 'dude', 'sweetheart',
                       'dearie', 'pet', 'petal', 'duck', 'ducky', 'poppet', 'lovey', 'chum', 'sunshine',
                       'yo'})
# Words without one of which a sentence holds no address for strip_addresses to drop.
_ADDRESS_WORDS = VOCATIVES | {'me', 'my'}


# Words said twice in a row by slip ("the the"), never twice on purpose.
DOUBLED = frozenset({'the', 'a', 'an', 'to', 'go', 'and', 'then', 'of', 'at', 'in', 'on', 'by', 'near',
                     'from', 'avoid', 'never', 'is', 'it', 'that'})


# Words before "in this order:" that only say to go to the list ("please visit these in order: ...").
_ORDER_LEADS = frozenset({'please', 'go', 'to', 'visit', 'check', 'these', 'them', 'the', 'following',
                          'places', ','})
# Order phrases a heading may end with ("today's stops, in this order: ..."): kept, after the list.
_HEADING_ORDERS: tuple[tuple[str, ...], ...] = (
    ('in', 'this', 'order'), ('in', 'that', 'order'), ('in', 'the', 'following', 'order'), ('in', 'order'),
    ('in', 'this', 'sequence'), ('in', 'sequence'))


def _list_in_order(tokens: list[str], i: int, out: list[str], verb: Sequence[str] = ()) -> int:
    """Put ``verb``, the list from ``tokens[i]`` to the end of its sentence and "in this order" into ``out``.

    Returns where the sentence ends.
    """
    end = next((k for k in range(i, len(tokens)) if tokens[k] in '.;!?'), len(tokens))
    out.extend([*verb, *tokens[i:end], ',', 'in', 'this', 'order'])
    return end


def strip_headings(tokens: list[str], notes: list[str]) -> list[str]:
    """Remove a heading before a colon that opens a sentence ("Morning routine for you, robot: ..."), noted.

    A heading names the list of tasks that follows (a word of :data:`TASK_NOUNS`) and holds no
    constraint word; a list of places before a colon ("the shelf, the cabinet: ...") is no heading.
    """
    out: list[str] = []
    i = 0
    n = len(tokens)
    while i < n:
        if i == 0 or tokens[i - 1] in '.;!?':
            c = next((k for k in range(i, min(n, i + 9)) if tokens[k] in PUNCT and tokens[k] != ','), -1)
            head = tokens[i:c] if c > i and tokens[c] == ':' else []
            order = next((t for t in _HEADING_ORDERS
                          if len(head) >= len(t) and tuple(head[-len(t):]) == t), ())
            if order and c + 1 < n:
                # "stops for today, in this order: a / b / c": the heading goes, its order is said
                # after the list (where the clause reader takes "a, b and c in this order")
                head = head[:-len(order)]
                while head and head[-1] == ',':
                    head.pop()
            counted = [w for k, w in enumerate(head) if not (   # "three things to do:": no count of visits
                w in NUMBER_WORDS and head[k + 1:k + 2] and head[k + 1] in TASK_NOUNS)]
            when = next((k for k in range(1, len(counted) - 1) if counted[k] in ('before', 'by') and
                         counted[-1] in _TIMES_OF_DAY and all(
                             w in _TIMES_OF_DAY or w in ORDINALS or w == 'the' for w in counted[k + 1:])), -1)
            if when > 0:
                counted = counted[:when]   # "couple of things before first period:": when, no place
            # "Just to check the cat has everything: ...": what the list is for
            aim = head[1:] if head[:1] == ['just'] else head
            purpose = aim[:2] in _WHAT_FOR
            if order and all(w in _ORDER_LEADS for w in head):
                # "in this order: a, b, c", "visit these in order: a, b, c": the list, then its order
                verb = [w for w in head if w in ('visit', 'check')][:1] or (
                    ['go', 'to'] if 'go' in head else [])
                i = _list_in_order(tokens, c + 1, out, verb)
                continue
            if head and c + 1 < n and (any(w in TASK_NOUNS for w in head) or purpose) and \
                    not carries_constraint(counted) and not _CHANGES & set(head) and \
                    head[0] not in ACTIVITY_VERBS and head[0] not in _COMMANDS and not any(
                        w in DETERMINERS and k > 0 and head[k - 1] in (',', 'and', 'or')
                        for k, w in enumerate(head)):
                notes.append(f'left out the heading "{" ".join(t for t in head if t != ",")}:"')
                i = _list_in_order(tokens, c + 1, out) if order else c + 1
                continue
        out.append(tokens[i])
        i += 1
    return out


_PAREN_RE = re.compile(r'\(([^()]{0,200})\)')
# "walk the loop (front desk, elevator, mail room)": the places of a route, in its order
_ROUTE_PAREN_RE = re.compile(r'\b(?:(?:the|that|this|my|your|our|usual|whole|same|regular|normal)\s+)+'
                             r'(?:loop|route|circuit|round|rounds|tour|lap|course|run)\s*\(([^()]{0,200})\)'
                             r'(?P<n>\s*,?\s*(?:twice|two times|three times|thrice|[2-5] times)'
                             r'(?! in a row))?',
                             re.IGNORECASE)
_ROUTE_SEP_RE = re.compile(r'\s*(?:,\s*(?:and\s+)?(?:then\s+)?|\s+and\s+(?:then\s+)?|\s+then\s+|\s*->\s*|'
                           r'\s+-+\s+|\s*>\s*)\s*', re.IGNORECASE)
_ROUTE_ITEM_RE = re.compile(r"[a-z0-9' ]+", re.IGNORECASE)


def _route_places(m: re.Match[str], notes: list[str]) -> str:
    """Read a route's places in parentheses as visits in a row, unless one is no short plain name."""
    items = [i.strip() for i in _ROUTE_SEP_RE.split(m.group(1).strip()) if i.strip()]
    if len(items) < 2 or any(not _ROUTE_ITEM_RE.fullmatch(i) or len(i.split()) > 4 or
                             carries_constraint(i.lower().split()) for i in items):
        return m.group(0)
    notes.append(f'read "{m.group(0)}" as the route of its places, in that order')
    # "the loop (...) twice": the route done twice, as "twice in a row" says
    return ' , then '.join(items) + (f' {m.group("n").strip(" ,")} in a row' if m.group('n') else ' ,')


def strip_parentheticals(text: str, notes: list[str]) -> str:
    """Leave out asides in parentheses ("the mug (the one with the chipped handle)"), noted.

    An aside holding a constraint word ("(but never the red one)") is read as a clause instead, and
    the places of a route ("walk the loop (front desk, elevator, mail room)") as visits in that order.
    """
    def aside(m: re.Match[str]) -> str:
        words = re.findall(r"[a-z0-9']+", m.group(1).lower())
        if len(words) == 1 and len(words[0]) <= 2 and words[0].isdigit():
            return m.group(0)   # "(2)": a list number, read by the tokenizer
        if carries_constraint(words) or words[:1] in (['then'], ['and']):
            return f', {m.group(1)} ,'
        notes.append(f'left out "({m.group(1).strip()})" (an aside)')
        return ' '
    if '(' not in text:
        return text
    text = _ROUTE_PAREN_RE.sub(lambda m: _route_places(m, notes), text)
    return _PAREN_RE.sub(aside, text) if '(' in text else text


def strip_frames(tokens: list[str], notes: list[str]) -> list[str]:
    """Remove frames around a request ("it would be great if you could ...", "time to ..."), noted."""
    text = ' ' + ' '.join(tokens) + ' '
    for pattern, repl in FRAMES:
        m = pattern.search(text)
        if m is not None:
            notes.append(f'left out "{m.group(0).strip(" ,.;!?")}" (asks for nothing)')
            text = ' ' + ' '.join(pattern.sub(repl, text).split()) + ' '
    return text.split()


# Nouns of time: "this evening" is not a place.
TIME_NOUNS = frozenset({'evening', 'morning', 'afternoon', 'night', 'week', 'weekend', 'day', 'moment',
                        'minute', 'second', 'sec', 'today', 'tonight', 'tomorrow', 'now', 'while'})


# "the red one", "that one": a thing, no count
_ONE_AFTER = frozenset(DETERMINERS) | PLACEHOLDER_ADJECTIVES


def has_constraint_word(tokens: Sequence[str]) -> bool:
    """Whether any token is a negation, order, time or count word (not a clock time: "at six")."""
    return any((t in CONSTRAINT_WORDS or t.isdigit()) and not (
        (t in NUMBER_WORDS or t.isdigit()) and k > 0 and tokens[k - 1] in ('at', 'around', 'about') and
        tokens[k + 1:k + 2] not in (['times'], ['time'])) and not (
        t == 'one' and k > 0 and tokens[k - 1] in _ONE_AFTER) for k, t in enumerate(tokens))


# After "keep" / "stay": words that make it a constraint ("keep away", "stay off"); "keep an eye
# on", "stay calm" ask for nothing about places.
_KEEP_CONSTRAINT = frozenset({'away', 'off', 'clear', 'out', 'far', 'back', 'your', 'well', 'in', 'on',
                              'within', 'inside', 'at', 'there', 'here', 'put', 'behind', 'outside', 'right',
                              'to', 'going', 'moving', 'visiting'})


def carries_constraint(tokens: Sequence[str]) -> bool:
    """Whether words hold a negation, an avoid or stay verb, an order or a count word.

    As :func:`has_constraint_word`, but "keep" and "stay" count only where they constrain where
    the robot goes ("keep away from", "stay in"), not in "keep an eye out", "stay calm".
    """
    words = [t for k, t in enumerate(tokens) if not (
        t in ('keep', 'stay') and (k + 1 >= len(tokens) or tokens[k + 1] not in _KEEP_CONSTRAINT)) and not (
        t == 'one' and k > 0 and tokens[k - 1] in DETERMINERS | PLACEHOLDER_ADJECTIVES)]   # "the red one"
    return has_constraint_word(words) or 'avoid' in words or any(w.startswith('avoid') for w in words)


# People a statement may be about ("a visitor thinks she dropped a glove").
PERSON_NOUNS = frozenset('''
lady gentleman man woman visitor visitors customer customers family guest guests curator librarian manager
archivist inspector cleaner cleaners staff kid kids child children grandmother grandfather grandma grandpa
mum mom dad mother father wife husband son daughter boss colleague neighbour neighbor neighbours neighbors
teacher nurse doctor patient patients boy girl baby toddler student students supplier delivery driver
gardener chef waiter owner tenant landlord friend friends people someone somebody everyone everybody nobody
guard caretaker porter receptionist volunteers animals pigeon pigeons cat dog dogs birds lifeguard trainer
carer guest customer technician electrician plumber vet housekeeper contractor contractors crew
grandchildren grandchild grandkids grandkid grandson granddaughter grandsons granddaughters nephew niece
agronomist farmer farmhand shepherd stockman herdsman conservator attendant docent
'''.split())
# People named without an article at the start of a statement ("customers keep asking ...").
_BARE_PEOPLE = frozenset({'customers', 'people', 'visitors', 'kids', 'children', 'staff', 'guests',
                          'students', 'patients', 'volunteers', 'cleaners', 'neighbours', 'neighbors'})
# Nouns that make a place of a person noun before them ("the staff room", "the nurses' station"); as
# head words, places people name: never a person, never a thing carried.
PLACE_HEADS = frozenset('''
room rooms station desk office area lounge entrance center centre toilet toilets bathroom bathrooms kitchen
door car park parking bay table chair bed block quarters corridor lift lifts lot zone wing hall canteen
cafeteria changing locker lockers stand counter gate bench shed garden playground pen basket bowl bed kennel
bedroom bedrooms suite suites house cabin cottage closet wardrobe lobby reception book fridge washroom
restroom restrooms shower showers exit cupboard apartment flat villa chalet tent ward garage bath baths
'''.split())
# Words of a rule about where to go: a clause holding one is never said "about people".
PLACE_RULE_WORDS = frozenset({
    'not', 'never', 'avoid', 'limits', 'bounds', 'forbidden', 'banned', 'away', 'clear', 'only', 'until',
    'till', 'unless', 'cannot', 'mustn', 'allowed'})
# ... and, in a reason ("because you must not ..."), words of an order, a count or a step too.
_STRONG = PLACE_RULE_WORDS | frozenset({'stay', 'keep', 'first', 'then', 'exactly', 'twice', 'once', 'go',
                                        'visit', 'bring', 'take', 'put'})


def is_reason(tail: Sequence[str]) -> bool:
    """Whether a part is a reason said after the request ("..., because the floor was just waxed")."""
    if len(tail) < 3 or tail[0] not in ('because', 'since', 'as', 'cos', 'cause'):
        return False
    if tail[0] == 'as' and tail[1] not in DETERMINERS and tail[1] not in STATEMENT_SUBJECTS:
        return False   # "as soon as", "as well"
    return not _STRONG & set(tail)


# How a remark of the speaker's own opens ("I'll meet you there", "I'd like to know whether ...").
_OWN_REMARK_LEADS: tuple[tuple[str, ...], ...] = tuple(sorted(
    [('i', 'will', v) for v in ('meet', 'be', 'see', 'catch', 'join', 'wait', 'follow', 'check', 'come',
                                'call', 'let', 'sort', 'deal', 'handle', 'take', 'grab', 'pick', 'text',
                                'ring')] +
    [lead + (v,) for lead in (('i', 'would', 'like', 'to'), ('i', 'want', 'to'), ('i', 'need', 'to'),
                              ('i', 'just', 'want', 'to'), ('i', 'just', 'need', 'to'), ('we', 'want', 'to'),
                              ('we', 'need', 'to'), ('i', 'would', 'love', 'to'))
     for v in ('know', 'see', 'check', 'find', 'hear', 'make', 'be', 'confirm', 'test', 'understand')] +
    [('i', 'am', 'out'), ('i', 'am', 'in'), ('i', 'am', 'at'), ('i', 'am', 'upstairs'),
     ('i', 'am', 'downstairs'), ('i', 'am', 'outside'), ('i', 'am', 'stuck'), ('i', 'am', 'locked'),
     ('i', 'have', 'locked'),
     # ("I think it is on the shelf" says where a thing is: not listed)
     ('i', 'hope'), ('i', 'wonder'), ('i', 'am', 'curious'), ('i', 'am', 'hoping'), ('i', 'am', 'worried'),
     # (with "I'd like to" left out before: "know whether it is warm", "see how you manage")
     ('know', 'whether'), ('know', 'if'), ('know', 'how'), ('see', 'how'), ('see', 'whether'),
     ('see', 'if'), ('find', 'out')],
    key=lambda t: -len(t)))


_OWN_REMARK_FIRST = frozenset(m[0] for m in _OWN_REMARK_LEADS)


def is_own_remark(tokens: Sequence[str]) -> bool:
    """Whether a sentence after the request is the speaker's own plan or wish ("I'll meet you there").

    Never one that asks the robot for something: "you" with a verb of going, or a rule word.
    """
    words = [t for t in tokens if t not in PUNCT]
    if not words or words[0] not in _OWN_REMARK_FIRST or \
            not any(tuple(words[:len(m)]) == m for m in _OWN_REMARK_LEADS):
        return False
    if has_constraint_word(words):
        return False   # ("I want to be sure you never go near the pond": a rule)
    return not any(words[k] == 'you' and words[k + 1:k + 2] and words[k + 1] in (
        'to', 'go', 'at', 'in', 'by', 'near', 'bring', 'take', 'visit', 'head', 'fly', 'stay', 'keep')
        for k in range(len(words)))


def is_person_statement(tokens: Sequence[str]) -> bool:
    """Whether a clause is said about people, not asked of the robot ("a lady says ...", "I can't leave").

    Its subject is a person (I, we, she, a visitor, my grandmother) and "you" or the robot is
    never named; "I need", "I'd like", "we want" are requests and never count.
    """
    if len(tokens) < 3 or 'you' in tokens or 'robot' in tokens or 'drone' in tokens or 'your' in tokens or \
            PLACE_RULE_WORDS & set(tokens):
        return False   # a rule is never left out ("the baby gate is off limits")
    k = 0
    if tokens[0] in ('i', 'we', 'he', 'she', 'someone', 'somebody', 'everyone', 'nobody'):
        k = 1
    elif tokens[0] in DETERMINERS and tokens[1] in PERSON_NOUNS:
        k = 2
    elif tokens[0] in _BARE_PEOPLE or tokens[0] in FAMILY_NAMES:
        k = 1
    elif tokens[0] in DETERMINERS and len(tokens) > 3 and tokens[2] in PERSON_NOUNS:
        k = 3
    if not k or k >= len(tokens):
        return False
    verb = tokens[k]
    if k + 1 == len(tokens) and not verb.endswith(('s', 'ed', 'ing')) and verb not in _SAID_ALONE:
        return False   # "then the student union": a place named for people, no verb ("the guests left")
    if verb in PLACE_HEADS or '_' in verb or tokens[k - 1] in PERSON_NOUNS and \
            k + 1 < len(tokens) and tokens[k + 1] in PLACE_HEADS and verb not in DETERMINERS:
        return False   # "the staff room", "the guest lounge", "the customer service desk": a place
    if tokens[-1] in PLACE_HEADS and len(tokens) - k <= 3 and not any(
            w in DETERMINERS or w in PREPOSITIONS or w in PUNCT for w in tokens[k:]):
        return False   # "the customer service desk", "the visitor parking lot": a place named for people
    if k == 1 and verb in ('will', 'shall') and tokens[0] in ('i', 'we') and \
            tokens[2] not in REQUEST_WORDS and \
            tokens[2] not in ('need', 'want', 'have', 'ask', 'be', 'get', 'let', 'tell', 'show', 'send'):
        return True   # "... and I'll bring her over": what the person will do
    return verb not in REQUEST_WORDS and verb not in ('need', 'needs', 'want', 'wants', 'would', 'd', 'like',
                                                      'will', 'must', 'should', 'have', 'has')


# Verbs said last after a person ("the guests left", "my son woke"): a statement, not a place's name.
_SAID_ALONE = frozenset({'left', 'went', 'came', 'got', 'said', 'ate', 'slept', 'sat', 'stood', 'fell', 'ran',
                         'woke', 'spoke', 'lost', 'forgot', 'paid', 'quit', 'won', 'knows', 'knew', 'saw',
                         'heard', 'rang', 'called', 'complained', 'agreed', 'refused', 'can', 'will', 'did',
                         'do', 'might', 'may', 'must', 'should', 'would', 'could', 'shall'})

# Verbs of what somebody else wants or is like, in a remark after the request ("marco gets chatty").
_OTHERS_WANT = frozenset({'wants', 'want', 'needs', 'need'})
_OTHERS_GET = frozenset({'gets', 'get'})
# "VIPs in at eight", "the band due at nine": people arriving at a time.
_ARRIVING = frozenset({'in', 'due', 'arriving', 'here', 'back', 'coming'})


# Words that point at a thing or a place, and of a place to be left alone, in what somebody wants.
# (not "his", "her", "their": "Arthur wants his wellies" names a belonging of the person, no place)
_POINTING = frozenset({'the', 'this', 'that', 'these', 'those', 'my', 'our', 'its'})
_NOBODY_THERE = frozenset({'nobody', 'noone', 'empty', 'alone', 'themselves', 'himself', 'herself', 'privacy',
                           'clear', 'quiet', 'free', 'peace'})


def is_others_remark(tail: Sequence[str], commands: frozenset[str]) -> bool:
    """Whether a part after the request says what somebody else wants or is like, asking the robot nothing.

    "..., Marco gets chatty", "..., marketing wants footage", "..., they want to settle up", "..., the
    gentleman there wants another", "..., VIPs in at eight". Never with "you", a word of a rule or a
    count, a command after "want to", or a place named after the verb ("chef needs the kitchen").
    """
    if len(tail) < 3 or 'you' in tail or 'your' in tail or PLACE_RULE_WORDS & set(tail) or \
            has_constraint_word(tail):
        return False
    s = 1
    if tail[0] in DETERMINERS:
        if tail[1] not in PERSON_NOUNS:
            return False
        s = 2
        while s < len(tail) and tail[s] in ('there', 'here', 'over'):
            s += 1   # "the gentleman there"
    elif tail[0] not in ('they', 'he', 'she') and (tail[0] in commands or tail[0] in STATEMENT_SUBJECTS or
                                                   not is_name_word(tail, 0, False)):
        return False
    if s + 1 >= len(tail):
        return False
    verb, rest = tail[s], tail[s + 1:]
    if verb in _ARRIVING and rest[0] == 'at' and len(rest) == 2 and (
            rest[1] in NUMBER_WORDS or rest[1] in ('noon', 'midnight')):
        return s == 1 and tail[0] not in STATEMENT_SUBJECTS   # "VIPs in at eight"
    if verb in _OTHERS_GET:
        return len(rest) <= 2 and rest[0] not in DETERMINERS and rest[0] not in PREPOSITIONS
    if verb not in _OTHERS_WANT:
        return False
    if rest[0] == 'to':
        return len(rest) > 1 and rest[1] not in commands and rest[1] not in ('be', 'have', 'see', 'get')
    # not a place or thing pointed at, nor who may be there ("the guests want the library to themselves",
    # "Marco wants nobody in the lab", "the vet needs the surgery empty")
    return not any(w in PLACE_HEADS or w in _POINTING or w in _NOBODY_THERE for w in rest)


# Subjects that point at things said before ("the other one", "one of them"): no count, no place.
_ONE_SUBJECTS: tuple[tuple[str, ...], ...] = (
    ('the', 'other', 'one'), ('the', 'other', 'ones'), ('one', 'of', 'them'), ('one', 'of', 'those'),
    ('one', 'of', 'these'), ('the', 'other', 'two'))


def is_statement(tokens: Sequence[str], np_end: int = 0) -> bool:
    """Whether a clause describes the world rather than asking the robot for something.

    Parameters
    ----------
    tokens:
        The clause, fillers stripped.
    np_end:
        Where a noun phrase at the start of the clause ends (0: none), for
        noun-phrase subjects ("the cat keeps...").
    """
    n = next((len(s) for s in _ONE_SUBJECTS if tuple(tokens[:len(s)]) == s), 0)
    if n and tokens[n:n + 1] and tokens[n] in FINITE_VERBS and tokens[n + 1:n + 2] != ['to'] and \
            not has_constraint_word(tokens[n:]) and 'you' not in tokens:
        return True   # "the other one has the sharp knives in it", "one of them has my hearing aid in it"
    if len(tokens) > 4 and tokens[-1] == 'yet' and 'not' in tokens and {'it', 'them', 'that', 'this'} & set(
            tokens) and not {'go', 'visit', 'avoid', 'near', 'enter', 'stay', 'keep', 'you'} & set(tokens):
        return True   # "cleanup crew hasn't gotten to it yet": how the scene stands
    if np_end and is_numbered_subject(tokens, np_end):
        # "table 4 wants ketchup", "table 12 are celebrating": a numbered place, said without its article
        return tokens[np_end + 1:np_end + 2] != ['to'] and not has_constraint_word(tokens[np_end:])
    if not tokens or has_constraint_word([t for k, t in enumerate(tokens) if k >= np_end and not (
            # "it needs more shade": an amount of something, no count of visits; and the number of a
            # name is no count ("aisle 7 is closed")
            t in ('more', 'less') and k > 1 and tokens[k - 1] in FINITE_VERBS and k + 1 < len(tokens) and
            tokens[k + 1] not in NUMBER_WORDS and tokens[k + 1] not in ('than', 'times', 'time', 'often'))]):
        return False
    if len(tokens) > 2 and tokens[0] not in DETERMINERS and tokens[1] in (
            'going', 'coming', 'happening', 'arriving', 'visiting', 'waiting', 'cooking', 'running') and \
            tokens[0] not in STATEMENT_SUBJECTS | {'you', 'keep', 'stop', 'start', 'go', 'be'} and \
            is_name_word(tokens, 0, False):
        return True   # "lots going on today", "guests arriving at noon"
    if len(tokens) > 2 and tokens[0] not in DETERMINERS and tokens[1] in ('is', 'are', 'was', 'were') and \
            (tokens[2] in STATES or tokens[2] in DEGREE_WORDS and tokens[3:4] and tokens[3] in STATES) and \
            tokens[0] not in STATEMENT_SUBJECTS | {'you', 'there', 'here'} and \
            is_name_word(tokens, 0, False):
        return True   # "floor is wet there", "gate was locked": the article left out, as people do
    if tokens[0] in ('our', 'my', 'his', 'her', 'their') and np_end == 0:
        # "our in-laws are visiting": a possessive subject the phrase reader did not take
        f = next((k for k in range(2, min(6, len(tokens))) if tokens[k] in FINITE_VERBS), -1)
        return f > 0 and tokens[f + 1:f + 2] != ['to']
    if tokens[0] in STATEMENT_SUBJECTS:
        if len(tokens) < 2 or tokens[1] in REQUEST_WORDS or (tokens[0] == 'it' and tokens[1] in (
                'is', 'was') and (len(tokens) < 3 or tokens[2] in PERMISSIVE or 'to' in tokens)) or (
                tokens[0] in ('this', 'that') and tokens[1] not in FINITE_VERBS):
            return False   # "it is fine to go ...", "it is important to ...": not a description
        # "we have to go...", "i have got to...": obligations are requests
        return not ('to' in tokens[1:4] and tokens[1] in ('have', 'has', 'got', 'am', 'are'))
    if np_end and tokens[0] in DETERMINERS:
        # the noun phrase may have swallowed the verb ("the cat keeps knocking...")
        f = statement_verb(tokens, np_end)   # not "the desk that is by..."
        return f > 0 and tokens[f + 1:f + 2] != ['to']
    return False


# Verbs of a numbered place said as the people at it ("table 4 wants ketchup", "table 12 are celebrating").
_NUMBERED_SUBJECT_VERBS = NUMBER_SUBJECT_VERBS | {'has', 'have', 'is', 'are', 'was', 'were'}


def is_numbered_subject(tokens: Sequence[str], np_end: int) -> bool:
    """Whether a clause starts with a numbered place without its article, then its verb ("table 4 wants")."""
    return 2 <= np_end < len(tokens) and tokens[0] not in DETERMINERS and \
        tokens[0] not in STATEMENT_SUBJECTS and (tokens[np_end - 1].isdigit() or
                                                 tokens[np_end - 1] in NUMBER_WORDS) and \
        tokens[np_end] in _NUMBERED_SUBJECT_VERBS


def statement_verb(tokens: Sequence[str], np_end: int) -> int:
    """Where the verb of a statement with a noun-phrase subject is (-1: none)."""
    return next((k for k in range(2, np_end + 1) if k < len(tokens) and (tokens[k] in FINITE_VERBS or (
        # "the kids left their shoes": a verb, not the side of something ("left of", "the left door")
        tokens[k] == 'left' and tokens[k + 1:k + 2] != ['of'] and tokens[k + 1:k + 2] != [] and
        (tokens[k + 1] in DETERMINERS or tokens[k + 1] in _LEFT_OBJECTS))) and
        tokens[k - 1] not in ('that', 'which', 'who', 'is', 'are')), -1)


# Words after "left" that make it a verb ("the kids left stuff everywhere").
_LEFT_OBJECTS = frozenset({'stuff', 'things', 'everything', 'toys', 'it', 'them', 'some', 'all', 'trash',
                           'garbage'})


def is_filler(tokens: Sequence[str], known_verbs: frozenset[str]) -> bool:
    """Whether words carry nothing to do: no place, no skill verb, no constraint word.

    Parameters
    ----------
    tokens:
        The words left over.
    known_verbs:
        Verbs of goals, deliveries and picks (a part holding one is an instruction).
    """
    words = [t for t in tokens if t not in PUNCT]
    if not words or has_constraint_word(words) or any(w in known_verbs for w in words):
        return False
    for k, w in enumerate(words):
        nxt = words[k + 1] if k + 1 < len(words) else ''
        # a determiner, or a preposition before a name word, starts a place ("the it office", "of blue room")
        if nxt and nxt not in TIME_NOUNS and (w in DETERMINERS or w in PREPOSITIONS and is_name_word(
                words, k + 1, False)):
            return False
        rel = match_relation(words, k)
        if rel is not None and rel[1] < len(words) and (words[rel[1]] in DETERMINERS or is_name_word(
                words, rel[1], False)):
            return False
    return True


def _by_first(phrases: tuple[tuple[str, ...], ...]) -> dict[str, tuple[tuple[str, ...], ...]]:
    out: dict[str, list[tuple[str, ...]]] = {}
    for p in phrases:
        out.setdefault(p[0], []).append(p)
    return {k: tuple(v) for k, v in out.items()}   # longest first, as in the source


_LEADS_BY_FIRST = _by_first(LEADS)
_COURTESY_BY_FIRST = _by_first(COURTESY)


# Timing words a rule may read ("visit b right away after a"): kept where landmarks are named.
TIMING: frozenset[tuple[str, ...]] = frozenset({('right', 'away'), ('at', 'once'), ('already',),
                                               ('straight', 'away')})
# Discourse fillers between commas ("go to the hall, like, now").
ASIDES: tuple[tuple[str, ...], ...] = (
    ('like',), ('you', 'know'), ('i', 'guess'), ('basically',), ('i', 'think'), ('honestly',), ('kinda',),
    ('sort', 'of'), ('i', 'suppose'), ('mind',), ('mind', 'you'), ('definitely',), ('certainly',),
    ('absolutely',), ('for', 'sure'), ('of', 'course'),
)   # not "uh", "um": they mark self-corrections


# Verbs whose "for" names what is sought or awaited, not who a thing is for ("look for the dog").
_FOR_VERBS = frozenset({'go', 'look', 'looking', 'wait', 'waiting', 'search', 'searching', 'ask', 'asking',
                        'call', 'calling', 'watch', 'head', 'come', 'check', 'listen', 'care', 'sub',
                        'cover'})


def _for_whom(tokens: Sequence[str], i: int) -> bool:
    """Whether ``tokens[i]`` is a "for" that can start a phrase naming who something is for."""
    return tokens[i] == 'for' and (i > 1 and tokens[i - 1] not in _FOR_VERBS or i == 0 and len(tokens) > 3 and
                                   ',' in tokens[2:5])   # "for the visitor, avoid the lobby"


# A clock time said as one word ("2pm", "10am", "noon").
_CLOCK_RE = re.compile(r'^(?:\d{1,2}(?:am|pm)|noon|midnight)$')
# Words that say which person ("for the new visitor"), before a person noun.
_PERSON_ADJECTIVES = frozenset({'new', 'next', 'old', 'young', 'little', 'morning', 'afternoon', 'evening',
                                'vip', 'important', 'elderly'})


# Groups of people a thing may be for ("for the PE class").
_GROUP_NOUNS = frozenset({'class', 'team', 'crew', 'group', 'kids', 'children', 'students', 'pupils',
                          'guests', 'visitors', 'customers', 'patients', 'staff', 'players', 'volunteers',
                          'residents'})


# Words before whose the thing is ("for the PE class", "for my grandma").
_WHOSE = frozenset({'the', 'my', 'our', 'your', 'his', 'her', 'their'})


def _beneficiary(tokens: Sequence[str], i: int) -> int:
    """Length of "for the visitor" / "for grandma" at ``i`` that ends its clause (who it is for), else 0."""
    j = i + 1
    if j < len(tokens) and (tokens[j] in _WHOSE or tokens[j] in ('a', 'an')):
        j += 1
        # "for the 2pm visitor", "for the 10 am visitor", "for the new guests": when or which one
        if j + 1 < len(tokens) and _CLOCK_RE.match(tokens[j]):
            j += 1
        elif j + 2 < len(tokens) and tokens[j].isdigit() and tokens[j + 1] in ('am', 'pm'):
            j += 2
        elif j + 1 < len(tokens) and tokens[j] in _PERSON_ADJECTIVES:
            j += 1
        elif j + 1 < len(tokens) and tokens[j + 1] in _GROUP_NOUNS and tokens[j] not in PUNCT:
            j += 1   # "for the PE class", "for the night crew"
    if j < len(tokens) and tokens[j] in _GROUP_NOUNS and tokens[i + 1:i + 2] and tokens[i + 1] in _WHOSE:
        j += 1   # "take the stopwatch out to the running track for the PE class": who it is for
        return j - i if j >= len(tokens) or tokens[j] in _CLAUSE_END else 0
    if j >= len(tokens) or not (tokens[j] in PERSON_NOUNS or tokens[j] in FAMILY_NAMES) or \
            tokens[j] in ('dog', 'dogs', 'cat', 'animals', 'birds', 'pigeon', 'pigeons', 'delivery'):
        return 0
    j += 1
    return j - i if j >= len(tokens) or tokens[j] in _CLAUSE_END else 0


# What pictures or footage are for ("hover above the pool deck for the wedding photos"): the visit is
# the task.
_PURPOSE_NOUNS = frozenset({'photos', 'photo', 'pictures', 'picture', 'footage', 'shoot', 'photoshoot',
                            'video', 'videos', 'shots', 'shot', 'website', 'brochure', 'newsletter', 'album',
                            'socials', 'records', 'record', 'report', 'archive'})


# Words that open a short noun phrase after "for" ("for the wedding photos", "wait for the crew").
_FOR_DETERMINERS = frozenset({'the', 'a', 'an', 'some', 'our', 'their', 'your', 'my'})
_OBJECT_PRONOUNS = frozenset({'me', 'us', 'him', 'her', 'them'})


def _plain_word(t: str) -> bool:
    """Whether ``t`` may be a word of a short noun phrase: letters only, no stopword, no constraint word."""
    return t.isalpha() and t not in STOPWORDS and t not in CONSTRAINT_WORDS


def _purpose_at(tokens: Sequence[str], i: int) -> int:
    """Length of "for the (wedding) photos" at ``tokens[i]``, ending the clause (0: none)."""
    j = i + 1
    if j >= len(tokens) or tokens[j] not in _FOR_DETERMINERS:
        return 0
    for k in range(j + 1, min(j + 4, len(tokens))):
        if tokens[k] in _PURPOSE_NOUNS and (k + 1 >= len(tokens) or tokens[k + 1] in _CLAUSE_END):
            return k + 1 - i
        if not _plain_word(tokens[k]):
            return 0
    return 0


def _wait_for(tokens: list[str], i: int) -> int:
    """Length of "and wait (there) for the cleaning crew" at ``i``: waiting where it is, for someone.

    Only a short noun phrase after "for" that ends the clause (no place after it: "wait for me at
    the door" is kept) and holds no rule word.
    """
    j = i + 1
    if tokens[j:j + 1] != ['wait']:
        return 0
    j += 1 + (tokens[j + 1:j + 2] in (['there'], ['here']))
    if tokens[j:j + 1] != ['for'] or j + 1 >= len(tokens):
        return 0
    if tokens[j + 1] in _OBJECT_PRONOUNS:
        return j + 2 - i if j + 2 >= len(tokens) or tokens[j + 2] in _CLAUSE_END else 0
    if tokens[j + 1] not in _FOR_DETERMINERS:
        return 0
    for k in range(j + 2, min(j + 6, len(tokens) + 1)):
        if k == len(tokens) or tokens[k] in _CLAUSE_END:
            return k - i if k > j + 2 else 0
        if not _plain_word(tokens[k]):
            return 0
    return 0


# What the person is busy with, said as the time of the request ("till I've finished changing him",
# "while I'm on this call", "before someone trips"): no event the robot can see, so no place and no order.
_PERSON_BUSY_RE = re.compile(
    r'(?: ,)? (?:(?:until|till) (?:i|we) (?:have |am |are )?(?:finished|done|through)'
    r'(?: (?:with )?[a-z]+ing)?(?: (?:him|her|them|it|this|that|up|(?:the|my|our) [a-z_]+))?|'
    r'while (?:i|we) (?:am|are) (?:on (?:the|this|a|my) (?:call|phone)|in (?:a|this|the|my) meeting|'
    r'(?!going|coming|heading|getting|walking|carrying)[a-z]+ing'
    r'(?: (?:him|her|them|it|dinner|lunch|breakfast|(?:the|my|our) [a-z_]+))?)|'
    r'before (?:someone|somebody|anyone|anybody|he|she|they) '
    r'(?:trips|falls|slips|steps on it|treads on it|breaks it|sees it|notices|wakes up|gets hurt))'
    r'(?= [,.;!?] | and | then | ?$)')


# The light or the weather said as a deadline ("before the light goes", "before it gets dark", "before the
# rain comes in"): a time, no event at a place that the robot could wait for or order a visit by.
_DEADLINE_RE = re.compile(
    r'(?: ,)? before (?:(?:the )?(?:light|sun|daylight|rain|tide|wind|weather|storm|fog|mist|'
    r'cloud|clouds|battery|batteries) (?:goes|fades|sets|dies|turns|changes|comes in|comes|starts|picks up|'
    r'rolls in|closes in|runs out|runs low|gets (?:worse|too low|too strong|low|bad))|it (?:gets|is|goes) '
    r'(?:dark|too dark|light|windy|too windy|dusk)|(?:dark|dusk|sunset|nightfall|sundown))'
    r'(?= [,.;!?] | and | then | ?$)')
_DEADLINE_WORDS = frozenset('''
light sun daylight rain tide wind weather storm fog mist cloud clouds battery batteries dark windy dusk sunset
nightfall sundown
'''.split())


# Words without which _PERSON_BUSY_RE cannot match: who is busy, and the word of time.
_BUSY_WHO = frozenset({'i', 'we', 'someone', 'somebody', 'anyone', 'anybody', 'he', 'she', 'they'})
_BUSY_WHEN = frozenset({'until', 'till', 'while', 'before'})


def _leave_out(tokens: list[str], pattern: re.Pattern[str], notes: list[str], why: str) -> list[str]:
    """Remove what ``pattern`` matches in the words, each part noted with ``why``."""
    text = ' ' + ' '.join(tokens) + ' '
    found = [m.group(0).strip(' ,') for m in pattern.finditer(text)]
    if not found:
        return tokens
    for said in found:
        notes.append(f'left out "{said}" ({why})')
    return pattern.sub('', text).split()


def strip_person_busy(tokens: list[str], notes: list[str]) -> list[str]:
    """Leave out what the person is busy with, said as the time of the request ("till I've finished").

    So too the light or the weather said as a deadline ("before the light goes").
    """
    words = set(tokens)
    if _DEADLINE_WORDS & words and 'before' in words and not PLACE_RULE_WORDS & words:
        # (never in a rule: "don't go there before dark")
        tokens = _leave_out(tokens, _DEADLINE_RE, notes,
                            'a time, no event the robot can wait for: check this')
        words = set(tokens)
    if not _BUSY_WHO & words or not _BUSY_WHEN & words:
        return tokens
    return _leave_out(tokens, _PERSON_BUSY_RE, notes,
                      'what the person is busy with: nothing the robot can wait for')


def strip_courtesy(tokens: list[str], notes: list[str], timing: bool = False) -> list[str]:
    """Remove courtesy and time-of-day phrases that end a clause ("go to the shed for me, then...").

    With ``timing``, phrases that time an event ("right away") are kept for the rules to read.
    Phrases said one after another ("twice tonight please") are all removed.
    """
    tokens = strip_person_busy(tokens, notes)
    for _ in range(3):
        before = len(tokens)
        tokens = _strip_courtesy_once(tokens, notes, timing)
        if len(tokens) == before:
            break
    return tokens


def _in_rule_clause(tokens: list[str], i: int) -> bool:
    """Whether the clause that ``tokens[i]`` ends holds a word of a rule about where to go."""
    k = i
    while k > 0 and tokens[k - 1] not in PUNCT:
        k -= 1
    return bool(PLACE_RULE_WORDS & set(tokens[k:i]))


_COPULAS = frozenset({'is', 'are', 'was', 'were', 'be', 'been'})


def _strip_courtesy_once(tokens: list[str], notes: list[str], timing: bool) -> list[str]:
    out: list[str] = []
    i = 0
    n = len(tokens)
    while i < n:
        hit = 0
        if i == 0 or tokens[i - 1] in PUNCT:
            for phrase in _LEADS_BY_FIRST.get(tokens[i], ()) + (START_LEADS if i == 0 else ()):
                m = len(phrase)
                if tuple(tokens[i:i + m]) == phrase and i + m < n and tokens[i + m] in (',', ':'):
                    notes.append(f'left out "{" ".join(phrase)}" (asks for nothing)')
                    hit = m + 1
                    break
            if hit:
                i += hit
                continue
        # (not after a copula: "it is okay" says how a thing is, "okay" is no courtesy there)
        if i > 0 and tokens[i - 1] not in DETERMINERS and tokens[i - 1] not in _COPULAS:
            for phrase in _COURTESY_BY_FIRST.get(tokens[i], ()):
                m = len(phrase)
                ends = i + m >= n or tokens[i + m] in _CLAUSE_END or (   # (or "..., please")
                    tokens[i + m] == 'please' and (i + m + 1 >= n or tokens[i + m + 1] in _CLAUSE_END)) or \
                    tokens[i + m:i + m + 2] in _WHAT_FOR
                if tuple(tokens[i:i + m]) == phrase and ends and not (timing and phrase in TIMING):
                    hit = m
                    break
        aside = False
        if not hit and _for_whom(tokens, i):
            hit = _beneficiary(tokens, i)
        if not hit and tokens[i] == 'for' and i > 0 and tokens[i - 1] not in PUNCT:
            hit = _purpose_at(tokens, i)
        if not hit and tokens[i] == 'and' and i > 0:
            hit = _wait_for(tokens, i)
        if not hit and i > 0 and tokens[i - 1] == ',':
            for phrase in ASIDES:
                m = len(phrase)
                if tuple(tokens[i:i + m]) == phrase and i + m < n and tokens[i + m] == ',':
                    hit, aside = m, True
                    break
        if hit and tokens[i + hit - 2:i + hit] == ['way', 'out'] and _in_rule_clause(tokens, i):
            # "don't go over the seal colony on the way out": the way to the goal, a scope (kept)
            out.extend(tokens[i:i + hit - 1] + ['there'])
            i += hit
            continue
        if hit and (hit > 1 or tokens[i] not in ('please', 'okay', 'ok', 'now')):
            notes.append(f'left out "{" ".join(tokens[i:i + hit])}" (asks for nothing)')
            i += hit
            if out and out[-1] == ',' and i < n and tokens[i] == ',':
                if not aside or i + 1 < n and tokens[i + 1] not in DETERMINERS and \
                        tokens[i + 1] not in STATEMENT_SUBJECTS and not is_name_word(tokens, i + 1, False):
                    # (", mind, that's how we lost the last one": the comma stays before a new clause)
                    out.pop()   # "don't, under any circumstances, enter": no commas are left
                i += 1   # (but "the bureau, definitely, Lily has been ...": one stays between two parts)
            continue
        out.append(tokens[i])
        i += 1
    return out


# Remarks that leave a choice or the pace to the robot ("your call", "take your time",
# "both are fine by me", "whichever is less busy"): a clause of their own that asks for nothing.
_REMARK_RE = re.compile(
    r'^(?:(?:and|but|so|honestly|really|i mean|i do not know) )*(?:'
    r'(?:it is )?(?:your (?:choice|call|pick|decision)|up to you|dealer s choice|dealer choice)'
    r'|(?:(?:i am |i m |i )?not (?:fussed|fussy|bothered|picky)|(?:i have )?no preference)'
    r'|(?:it )?(?:does not|do not|will not|would not) matter(?: (?:which|which one|to me|either way))?'
    r'(?: (?:first|order|comes first|you do first))?'
    r'|no matter (?:which|what)(?: (?:order|one|way|one first|comes first))?'
    r'(?: (?:you|we) (?:pick|choose|go for|go with|take|do|use))?'
    r'|(?:what|whatever|whichever|which) (?:you )?(?:prefer|like|want|choose)(?: best| more)?'
    r'|(?:you )?(?:choose|pick|decide)(?: which(?: one)?)?'
    r'|(?:either|one|any) of (?:them|those|the two) (?:is|will be|would be) (?:enough|fine|ok|okay|plenty)'
    r'|i (?:need|want) (?:both|all|each|them all|all of them|both of them) '
    r'(?:checked|done|visited|covered|seen)'
    r'|(?:i )?(?:honestly |really )?(?:do not|will not) (?:mind|care)'
    r'(?: which| either way| (?:about )?(?:what|which|the) order)?'
    r'(?: (?:one|option|way|route))?(?: you (?:go for|pick|choose|take|use|do))?'
    r'|take (?:your|as much) time(?: (?:as you need|about it|with it))?'
    r'|(?:both|either|either one|either of them|both of them|any of them|any)'
    r'(?: (?:location|place|option|destination|room|spot|route|way))? (?:is|are|would be|will be) '
    r'(?:(?:perfectly|equally|entirely) )?(?:fine|ok|okay|good|alright|great|acceptable)'
    r'(?: (?:by|with|for|to) me| for (?:this|the) (?:test|run|task|job|trial|exercise))?'
    r'|(?:(?:i |we )?(?:am|are) )?(?:fine|happy|ok|okay) with (?:either|both|any|whichever)(?: \w+)?'
    r'(?: (?:is|are|s) (?:less |more |the )?\w+(?: to \w+)?)?'
    r'|whichever(?: \w+)? (?:is|are|s|one is) (?:less |more |the )?\w+(?: (?:to \w+|for you|to you))?'
    r'(?: (?:right now|now|today|at the moment))?'
    r'|(?:that|the) order (?:matters|is important)(?: to (?:me|us))?'
    r'|(?:any|any one|anyone|either one|whichever one|whichever)'
    r'(?: of (?:them|those|these|the (?:two|three|four|five)(?: \w+)?))?(?: (?:will do|is fine|works))?'
    r'|(?:whichever|whatever)(?: one)? you (?:get to|reach|see|like|want|prefer|come to|find|spot)(?: first)?'
    r'|wherever(?: is| s)? (?:clearer|closer|nearer|quieter|easier|safer|less \w+)'
    # "the sofa or the recliner, wherever Joan's sat": whichever the person is at
    r'|wherever (?:he|she|they|it|[a-z]+) (?:is|are|has|have) (?:got to|gone|gone to|sat|sitting|settled|'
    r'ended up|wandered off to|hiding|sat down|parked|put (?:himself|herself|themselves))'
    r'|(?:whichever|which)(?: one)? (?:is |s )?(?:more )?'
    r'(?:easier|easiest|closer|close|nearer|near|quicker|faster|nearest)'
    r'(?: (?:for you|to you|to get to))?'
    r'|(?:either|any|either one|any one) works(?: (?:for me|fine))?(?: honestly)?'
    r'|(?:i )?do not care which (?:1|one)'
    r'|i (?:just |only )?need you to (?:see|check|find out|look) (?:if|whether) [a-z ]+'
    r'|pick one(?: and go)?'
    r'|(?:for me|to me) (?:it )?(?:is|s) (?:all )?the same|(?:it )?(?:is|s) (?:all )?the same (?:for|to) me'
    # "I want you to learn where it lives", "so you know where they go": where a thing is kept, to remember
    r'|(?:(?:i|we) (?:want|would like|need) you to |(?:so )?(?:that )?you (?:can |will )?)'
    r'(?:learn|remember|know|memori[sz]e|note|see) where (?:it|they|this|that|she|he) '
    r'(?:lives?|is|are|goes|go|belongs?|sits?|stays?|is kept|are kept)'
    r'|(?:learn|remember|memori[sz]e) where (?:it|they|this|that|she|he) '
    r'(?:lives?|is|are|goes|go|belongs?|sits?|stays?|is kept|are kept)'
    r'|i (?:just |only )?need (?:you )?(?:to )?(?:hold|carry|help (?:me )?with|mind|keep|look after|watch) '
    r'(?:something|this|that|it|a few things|some things|a thing|stuff)'
    r'(?: (?:for me|for a (?:second|minute|bit)))?'
    r'|i (?:will|ll|shall) be (?:there|right there|with you|along|over|back|down|up)'
    r'(?: (?:in a (?:minute|moment|second|sec|bit|few minutes|jiffy)|shortly|soon|in five|in ten|later|'
    r'in (?:a couple of|two|three|five|ten|fifteen|twenty|thirty|\d+) (?:minutes|mins|seconds|secs)))?'
    r'(?: with (?:the|my|your|some) [a-z ]+)?'
    # "I'll meet you there with the quad": the speaker comes to where the robot goes (no place of its own)
    r'|(?:and )?i (?:will|ll|shall) (?:meet|see|join|find|catch up with) you '
    r'(?:there|here|in a bit|shortly|soon)'
    r'(?: (?:in a (?:minute|moment|second|sec|bit|few minutes|jiffy)|shortly|soon|later))?'
    r'(?: with (?:the|my|your|some) [a-z ]+)?'
    # "..., I want you on hand": be there, ready (where the request sends the robot)
    r'|(?:i|we) (?:want|need|would like|will want|will need) you (?:to be )?(?:on hand|handy|nearby|close by|'
    r'around|about|on standby|standing by|ready)(?: (?:just )?in case| for (?:it|her|him|them|that))?'
    r'|i (?:only |just )?need (?:one|one of them|either|either of them|one of the two) '
    r'(?:looked at|checked|done|visited|seen)'
    r'|(?:be )?careful(?: (?:now|please|with it|with them|though))?'
    r'|(?:(?:that|this|it) )?is (?:literally |really |just )?'
    r'(?:the only (?:stop|place|goal|errand|task|thing|job)|all|it)'
    r'(?: (?:for )?(?:today|now|'
    r'tonight|this time))?'
    r')$')


# "(avoid X until Y;) after that it's ok", "then it should be empty": the place held back is free
# again once the rule ends, which the rule says already. Read only after "after that" / "then" ("it's
# fine" alone may retract a rule: "avoid the hall. actually it's fine").
_FREE_AGAIN_RE = re.compile(
    r'^(?:after that |afterwards |from then on |from there on )?(?:, )?'
    r'(?:it|that|they|this|the rest) (?:is|are|s|should be|will be|would be|ought to be|becomes|gets) '
    r'(?:all |totally |completely |perfectly |probably |then )?'
    r'(?:ok|okay|fine|alright|allowed|free|clear|empty|quiet|safe)(?: (?:again|to go|by me))?'
    r'(?: (?:after that|afterwards|from then on))?$')


def is_free_again(tokens: Sequence[str]) -> bool:
    """Whether words say a place is free again ("it's ok", "it should be empty"), no rule of their own."""
    return bool(tokens) and _FREE_AGAIN_RE.match(' '.join(tokens)) is not None


_REMARK_STARTS = frozenset({'either', 'whichever', 'i', 'any', 'both', 'no', 'it', 'does', 'do', 'your',
                            'and',
                            'up', 'what', 'whatever', 'which', 'you', 'not', 'that', 'for'})


_REMARK_VERBS = frozenset({'go', 'visit', 'pick', 'choose', 'take', 'bring', 'check', 'use', 'try', 'is',
                           'are'})


def set_off_remarks(tokens: list[str], notes: list[str]) -> list[str]:
    """Leave out a remark that ends a sentence unmarked ("... the loveseat either one is fine"), noted."""
    out: list[str] = []
    start = 0
    for i, t in enumerate(tokens + ['.']):
        if t in '.;!?' or i == len(tokens):
            sentence = tokens[start:i]
            cut = next((j for j in range(2, len(sentence) - 1)
                        if sentence[j] in _REMARK_STARTS and sentence[j - 1] not in PUNCT and
                        sentence[j - 1] not in _DANGLING and sentence[j - 1] not in _REMARK_VERBS and
                        is_remark(sentence[j:])), -1)
            if cut > 0:
                lead = max((k for k in range(cut) if sentence[k] in PUNCT), default=-1) + 1
                if is_remark(sentence[lead:]):
                    cut = -1   # "..., i am not fussy": set off already
            if cut < 0:
                # "either the greenhouse or the cold frame, I only need one looked at": a remark after a
                # comma that ends a sentence (the alternatives would take it in)
                c = max((k for k in range(2, len(sentence) - 1) if sentence[k] == ','), default=-1)
                if c > 0 and 'or' in sentence[:c] and sentence[c + 1] in ('i', 'we') and \
                        is_remark(sentence[c + 1:]):
                    cut = c
            if cut > 0:
                notes.append(f'left out "{" ".join(sentence[cut:])}" (asks for nothing)')
            out.extend(sentence[:cut] if cut > 0 else sentence)
            out.extend(tokens[i:i + 1])
            start = i + 1
    return out


def is_remark(tokens: Sequence[str]) -> bool:
    """Whether words are a remark that leaves a choice or the pace to the robot ("your call")."""
    return bool(tokens) and _REMARK_RE.match(' '.join(tokens)) is not None


# "you" in set phrases that address nobody ("would you believe", "before you know it").
_IDLE_YOU: tuple[tuple[str, ...], ...] = (
    ('would', 'you', 'believe'), ('would', 'you', 'believe', 'it'), ('before', 'you', 'know', 'it'),
    ('you', 'know'), ('you', 'see'), ('mind', 'you'), ('thank', 'you'), ('bless', 'you'),
    ('i', 'tell', 'you'),
    ('if', 'you', 'ask', 'me'), ('can', 'you', 'imagine'))
# Words of a rule about places: a sentence holding one is never a story (“the hall is off limits”).
_STORY_RULE_WORDS = frozenset({
    'avoid', 'avoiding', 'limits', 'bounds', 'forbidden', 'banned', 'prohibited', 'allowed', 'permitted',
    'away', 'clear', 'steer', 'dangerous', 'unsafe', 'hazardous', 'robot', 'drone', 'yourself', 'your'})
# Verbs after a named subject that make the sentence a story ("Harold bought it", "Derek says ...").
_STORY_VERBS = frozenset('''
says said bought took left told thinks thought rang called came went gets got is was has had keeps kept
will would did does loves hates likes used moved broke fixed planted put set lost found rearranged
always never usually often still just only
leaves lives plays hides sleeps makes loses forgets drops
'''.split())
_STORY_LEADS = frozenset({'oh', 'well', 'and', 'but', 'so', 'anyway', 'honestly', 'now', 'mind', 'although',
                          'though', 'because'})


def is_story(sentence: Sequence[str], commands: frozenset[str]) -> bool:
    """Whether a whole sentence tells the person's story and asks the robot for nothing.

    "I left my thimble there, but I'll look for it myself once my knees have warmed up.",
    "Harold bought it the year we married.", "The light down there has been flickering.":
    the subject is a person or a thing other than the robot, with a verb of its own (not a
    request: "I need", "I'd like you to"), the robot is not addressed ("you", but for set
    phrases such as "would you believe"), no part starts with a command (``commands``), and
    no word of a rule about places is in it. Order and time words ("once", "never", "first")
    may be in it: they order the person's day, not the robot's task.
    """
    words = [t for t in sentence if t not in PUNCT]
    while words and (words[0] in _STORY_LEADS or words[0] in INTERJECTIONS or words[0] in VOCATIVES):
        words = words[1:]
    if words[:1] == ['i'] and words[1:2] and words[1] in ('think', 'guess', 'believe', 'reckon', 'suppose'):
        words = words[2:]   # "I think it is on the shelf": where the thing is
    if len(words) < 3 or _STORY_RULE_WORDS & set(words):
        return False
    text = ' ' + ' '.join(words) + ' '
    if any(p in text for p in (' has to be ', ' have to be ', ' must be ', ' goes for ', ' go for ',
                               ' same ', ' comes ', ' come ', ' last ', ' first ')) and \
            words[0] not in ('i', 'we'):
        return False   # "the bank has to be last", "the same goes for the vase": about the task
    if any(p in text for p in (' come after ', ' comes after ', ' come before ', ' comes before ',
                               ' come first ', ' comes first ', ' come last ', ' comes last ',
                               ' has to come ', ' have to come ', ' must come ', ' needs to come ',
                               ' need to come ')):
        return False   # "I don't care which comes first, but the window has to come after both": an order
    for phrase in _IDLE_YOU:
        text = text.replace(' ' + ' '.join(phrase) + ' ', ' ')
    if ' you ' in text or ' keep off ' in text or ' keep out ' in text or ' stay ' in text:
        return False
    # no part of it is a command ("..., so go to the shed")
    for k, t in enumerate(sentence):
        if t in commands and (k == 0 or sentence[k - 1] in PUNCT or sentence[k - 1] in (
                'and', 'then', 'so', 'but', 'please', 'just')):
            return False
        if t in ('never', 'not') and k + 1 < len(sentence) and sentence[k + 1] in commands:
            return False   # "..., but never go to the garage": a rule, never a story
    first, second = words[0], words[1]
    if first in ('it', 'that', 'this', 'they', 'he', 'she') and second in ('is', 'are', 'was', 'were') and (
            words[2] in DETERMINERS or words[2] in PREPOSITIONS or
            words[2] in ('one', 'ones', 'where', 'here')):
        return False   # "it's the one by the sink", "they are in the kitchen": which thing, or where
    if first in ('i', 'we'):
        if second in ('am', 'are') and words[2] not in _HERE_OR_ASKING and words[2] not in PREPOSITIONS:
            return True   # "I'm halfway through it", "we are expecting guests"
        return second not in REQUEST_WORDS and second not in ('need', 'want', 'wanted', 'needed', 'expect')
    if first in ('he', 'she', 'they', 'it', 'that', 'there') or first in FAMILY_NAMES:
        return second not in ('is', 'was') or words[2] not in PERMISSIVE
    if first in ('my', 'our', 'his', 'her', 'their') or first in ('the', 'a') and second in PERSON_NOUNS:
        return not _OTHERS_WANT & set(words[1:5])
    if first == 'the' or len(first) > 3 and first.endswith('s') and first not in commands and \
            first not in STOPWORDS_STORY and first not in PRONOUN_OBJECTS and second not in FINITE_VERBS and \
            is_name_word(words, 0, False) and is_name_word(words, 1, True):
        # "the light down there has been flickering", "Lily's flowers are in it" (a possessive name):
        # a finite verb within the first words
        f = next((k for k in range(2, min(6, len(words))) if words[k] in FINITE_VERBS or
                  words[k] in ('has', 'had', 'will')), -1)
        if f > 0 and f + 3 == len(words) and words[f] in ('is', 'are') and words[f + 1] in (
                'in', 'on', 'inside', 'under') and words[f + 2] in ('it', 'them', 'there'):
            return True   # "Lily's flowers are in it": what is in the thing named before
        if f < 0 or {'needs', 'need', 'wants', 'want', 'one', 'that', 'which', 'who', 'and', 'or'} & set(
                words[1:f + 1]):
            return False   # "the table that is next to ...", "the mug and the jar are ..."
        return not (words[f] in ('is', 'are', 'was', 'were') and f + 1 < len(words) and (
            words[f + 1] in PREPOSITIONS or words[f + 1] in DETERMINERS or words[f + 1] in (
                'next', 'left', 'right', 'behind', 'between', 'under', 'beside', 'above', 'below')))
    # a name said without an article ("Harold bought it", "Margaret's staying tonight")
    return first not in commands and first not in DETERMINERS and first not in STOPWORDS_STORY and \
        second in _STORY_VERBS and is_name_word(words, 0, False)


# Events people time their day by ("mtg starts at 10", "big all-hands at 3"): never a place.
_EVENTS = frozenset('''
meeting meetings mtg call calls standup huddle sync lunch dinner breakfast interview interviews presentation
demo review appointment party event session training class lecture briefing workshop webinar hands
inspection pickup tour
'''.split())
# Verbs of an event's time ("the meeting starts at 10").
_EVENT_VERBS = frozenset({'starts', 'begins', 'ends', 'finishes', 'kicks', 'wraps', 'is', 'was'})


def is_schedule(words: Sequence[str]) -> bool:
    """Whether words only say when an event is ("mtg starts at 10", "big all-hands at 3 today").

    The subject ends in an event noun (a meeting, a call, an all-hands: never a place) or has a
    verb of time ("the tour starts at noon"), then "at"/"around" and a clock time, and at most a
    day word after it. Such a sentence asks the robot for nothing.
    """
    words = [t for t in words if t not in PUNCT]
    k = next((k for k, t in enumerate(words) if t in ('at', 'around', 'by')), -1)
    if k < 1 or k + 1 >= len(words):
        return False
    time = words[k + 1:]
    if _CLOCK_RE.match(time[0]) or time[0].isdigit() and int(time[0]) <= 24 or time[0] in NUMBER_WORDS and \
            NUMBER_WORDS[time[0]] <= 12:
        time = time[1:]
    else:
        return False
    while time and time[0] in ('am', 'pm', 'oclock', 'o', 'clock', 'sharp', '30', '15', '45', '00', ':'):
        time = time[1:]
    if time not in ([], ['today'], ['tonight'], ['tomorrow'], ['this', 'morning'], ['this', 'afternoon']):
        return False
    subject = words[:k]
    if subject[-1:] and subject[-1] in ('off', 'up') and subject[-2:-1] in (['kicks'], ['wraps']):
        subject = subject[:-1]
    timed = subject[-1] in _EVENT_VERBS and len(subject) > 1
    if timed:
        timed = subject[-1] not in ('is', 'was')   # "the call is at 3": an event, said as one
        subject = subject[:-1]
    if subject[:1] and subject[0] in ('the', 'a', 'our', 'my', 'this', 'that', 'their', 'his', 'her'):
        subject = subject[1:]
    if not subject or len(subject) > 3 or has_constraint_word(subject) or any(
            t in ('you', 'go', 'visit', 'avoid', 'stay', 'keep', 'be', 'come') for t in subject):
        return False
    return subject[-1] in _EVENTS or timed and subject[-1] not in PLACE_HEADS and words[k] != 'by'


# Participles of work a robot that goes, picks and places cannot do ("need the invoices pulled").
_PEOPLES_WORK = frozenset('''
pulled signed printed copied scanned filed shredded stamped reviewed approved faxed emailed laminated
stapled notarized photocopied proofread typed translated invoiced processed sorted counted
'''.split())


def is_paperwork(words: Sequence[str]) -> bool:
    """Whether words say what the person needs done to papers ("need the 2023 invoices pulled").

    "(I/we) need (the/my/some) X <participle>" where the participle is work on papers no robot
    does (signed, printed, filed...): why the robot is sent, asking it for nothing more. A year in
    the name is no count.
    """
    words = [t for t in words if t not in PUNCT]
    if words[:1] in (['i'], ['we']):
        words = words[1:]
    if words[-1:] and words[-1] in ('today', 'asap', 'now', 'tonight', 'tomorrow'):
        words = words[:-1]
    if len(words) < 3 or words[0] not in ('need', 'needs', 'want') or words[1] == 'you' or \
            words[-1] not in _PEOPLES_WORK:
        return False
    thing = [t for t in words[1:-1] if t not in _PEOPLES_WORK and not (t.isdigit() and len(t) == 4)]
    return bool(thing) and thing[0] in ('the', 'my', 'our', 'some', 'these', 'those', 'all') and \
        not carries_constraint(thing) and 'you' not in thing


# After "I am": words that say where the person is or what they ask ("I'm asking you to ...").
_HERE_OR_ASKING = frozenset({'going', 'asking', 'telling', 'sending', 'to', 'here', 'there', 'sitting',
                             'waiting', 'standing', 'lying', 'back', 'off', 'out', 'coming', 'not',
                             'expecting'})
PRONOUN_OBJECTS = frozenset({'this', 'that', 'these', 'those', 'its', 'his', 'hers', 'ours', 'yours',
                             'theirs'})
STOPWORDS_STORY = frozenset({'please', 'if', 'when', 'once', 'after', 'before', 'only', 'never', 'do', 'not',
                             'no', 'then', 'first', 'just', 'also', 'either', 'both', 'each', 'every', 'all',
                             'here', 'this', 'these', 'those'})


# What a person wants of the robot, said as the reason to go ("chef's shouting for you", "Sofia
# needs a hand with it", "Mr. Alvarez would like a word"): it names no place and asks for nothing
# the formula can hold (the place is the one the request names).
_SUMMONS_RE = re.compile(
    r'^(?:(?:and|but|so|oh|because|since|as|cos) )?(?P<who>[a-z_]+(?: [a-z_]+){0,2}?) (?:'
    r'(?:is|are|was|were|has been|have been|keeps|keep) (?:shouting|calling|asking|looking|yelling|screaming|'
    r'waiting|hollering|crying out) (?:for|after) you'
    r'|(?:has |have )?(?:asked|called|shouted|is asking|are asking) (?:for|after) you'
    r'|(?:wants|want|would like|needs|need|could use|could do with|is after|are after|would love) '
    r'(?:a (?:quick )?(?:word|hand|chat)|(?:some )?help|a bit of help|'
    r'to (?:see|talk to|speak to|have a word with) you)(?: with (?:it|this|that|them|you|something))?'
    r'|(?:wants|want|would like|needs|need) to (?:run through|go over|talk through|talk about|discuss|'
    r'sort out|review) (?:the|some|a few) [a-z]+(?: [a-z]+)? with you'
    r')(?: (?:again|now|right now|too|as well|urgently|first))?$')
# Words that may not be the person of a summons: the robot, a rule, a place word or a pronoun for the robot.
_NOT_WHO = frozenset({'you', 'i', 'robot', 'drone', 'it', 'there', 'here', 'this', 'that', 'which', 'who',
                      'what', 'where'}) | CONSTRAINT_WORDS | PREPOSITIONS


def is_summons(tokens: Sequence[str], ordered: bool = False) -> bool:
    """Whether a clause says who wants the robot, and nothing else ("chef's shouting for you").

    The person is a name, a person noun or a title and name ("the Garcias", "Mr Alvarez",
    "chef"), with no preposition (so no place: "the guest at table 4 asked for you" is not
    one) and no rule word. A trailing "first" is allowed only where it repeats the order the
    request itself gave (the caller checks that).
    """
    words = [t for t in tokens if t not in PUNCT]
    if len(words) < 3:
        return False
    m = _SUMMONS_RE.match(' '.join(words))
    if m is None:
        return False
    if words[-1] == 'first' and not ordered:
        return False   # "..., Maria wants a word first": an order of its own
    who = m.group('who').split()
    if who[0] in DETERMINERS:
        # "the Garcias", "the chef": people, not "the kitchen needs a hand"
        who = who[1:]
        if not who or not (who[-1] in PERSON_NOUNS or who[-1].endswith('s') and who[-1] not in PLACE_HEADS):
            return False
    return bool(who) and not _NOT_WHO & set(who) and not any('_' in w for w in who)
