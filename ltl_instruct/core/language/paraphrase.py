"""Paraphrases rewritten to the one phrasing the clause reader knows, before it reads.

Many ways of saying the same thing map to one form, so the rules that read a form
need not know every way to say it:

- finishing a step: "when you're done there", "once finished", "after you're through
  with that" -> ``then``;
- passes and trips: "make three passes over X", "do two laps around X" -> "go over X
  three times";
- counts: "once and only once", "one time only" -> ``exactly once``;
- looking at a place: "have a look at", "take a peek at", "go see", "pay a visit to"
  -> ``visit``; "check whether X is closed" -> "check X is closed" (the rest is left
  to the reader, which leaves out words that ask for nothing, noted);
- emphasis inside avoidance: "stay well away from", "keep right away from" -> "stay
  away from";
- goals stated as a fact: "your goal is X", "the destination is X" -> "go to X".

Each rewrite works on the token list; none adds a place or a constraint that the
words did not name.
"""
from __future__ import annotations

import re
from typing import Any

from ltl_instruct.core.language.phrases import PhraseParser, singular

_DONE = (r'(?:(?:when|once|after|as soon as) (?:you are |you have |you re |you |it is |that is |'
         r'this is )?(?:done|finished|finish|through with (?:that|it|this))'
         r'(?: (?:there|here|with (?:that|it|this|them)|in there|over there))?)'
         # "after you've done the church spire": done a place, visited it (not "when finished")
         r'(?! (?:the|my|your|our|a|an|both|each)\b)')


# a name of a few words, none of them a connective
_NAME = r'(?:(?!(?:and|or|then|followed|the)\b)[a-z0-9_]+)(?: (?!(?:and|or|then|followed)\b)[a-z0-9_]+){0,4}'

# a place's name in a route, none of its words a verb of going or a connective
_ROUTE_NAME = (r'(?:(?!(?:and|or|then|the|go|visit|do|check|hit|to)\b)[a-z0-9_]+)'
               r'(?: (?!(?:and|or|then|followed|go|visit|do|check|hit|to)\b)[a-z0-9_]+){0,4}')

# a word of a name, none of the words of a clause's frame
_NOUN = r'(?!(?:is|are|was|were|has|have|had|then|to|go|and|or|not|too|as|it|they|will|can|so)\b)[a-z0-9_]+'


_NOUN_LEADS = frozenset({'the', 'a', 'an', 'my', 'your', 'our', 'this', 'that', 'his', 'her', 'their'})
_VERB_LEADS = frozenset({'and', 'then', 'to', 'must', 'please', 'just', 'go', 'should', 'will', 'can', 'you',
                         'come', 'now', 'first', 'or', 'but', 'not', 'never'})


def _named_stand(m: 're.Match[str]') -> bool:
    """Whether "stand" / "sit" ... ends a name ("the armor stand next to the fireplace"), not a verb."""
    before = m.string[:m.start()].split()[-3:]
    return len(before) >= 2 and before[-1] not in _VERB_LEADS and (
        before[-2] in _NOUN_LEADS or len(before) == 3 and before[-3] in _NOUN_LEADS and
        before[-2] not in _VERB_LEADS)


_REWRITES: tuple[tuple[re.Pattern[str], Any], ...] = tuple((re.compile(p), r) for p, r in (
    # "remain clear of X", "remaining well away from X": stay clear of it
    (r' remain(?P<g>ing)? (?=(?:well |safely |completely )?(?:clear|away|out|off) )',
     lambda m: ' staying ' if m.group('g') else ' stay '),
    # how long the task lasts, said as the span of the run ("for the entire flight", "for the duration of
    # the task", "throughout the flight", "over the course of the run"): the whole time (after a count, the
    # visits are counted over the run anyway: left out)
    # (not "either is fine for this test": the span says how long, "entire", "duration of", "throughout")
    (r'(?<= )(?P<c>(?:times|twice|once|thrice) )?(?:(?:for|during|throughout|over) (?:the|this|your) '
     r'(?:(?:entire|whole|full|complete) |(?:duration|course|length) of (?:the|this|your) )|throughout '
     r'(?:the|this|your) )'
     r'(?:[a-z]+ )?(?:flight|task|mission|run|trip|job|operation|procedure|test|session|visit|shift|errand)'
     r'(?= [,.;!?] | ?$)',
     lambda m: m.group('c') or 'the whole time'),
    # "either do the lab then the pharmacy or pharmacy then the lab": the two orders of the same two
    # places, any order (the article may be left out of either saying)
    (r'(^ | [,.;!?] | and | but )(?:either )?(?:(?P<v>go to|visit|do|check|hit) )?(?:the )?'
     r'(?P<x>' + _ROUTE_NAME + r') (?:, )?then (?:(?:go to|visit|do|check|hit) )?(?:the )?'
     r'(?P<y>' + _ROUTE_NAME + r') (?:, )?or (?:(?:go to|visit|do|check|hit) )?(?:the )?(?P=y) '
     r'(?:, )?then (?:(?:go to|visit|do|check|hit) )?(?:the )?(?P=x)'
     r'(?= [,.;!?] | ?$| (?:up to you|your (?:call|choice)|whichever|either way|i do not (?:mind|care)|'
     r'does not matter)\b)',
     lambda m: (lambda a: f'{m.group(1)}{m.group("v") or "go to"} {a}{m.group("x")} and {a}{m.group("y")} '
                          'in any order')('the ' if ' the ' in m.group(0) else '')),
    # "once you are at the gantry, the pit no longer matters": a place said to be fine (not "the order")
    (r'(?<= )(the|that|this) ((?:(?!order\b|sequence\b|route\b)[a-z0-9_]+ ){0,3}?'
     r'(?!order\b|sequence\b|route\b|rest\b)[a-z0-9_]+) '
     r'(?:no longer matters|does not matter(?: any ?more)?|is no longer (?:an issue|a problem|a concern))'
     r'(?= [,.;!?] |$)',
     r'\1 \2 is fine'),
    # "the orchard first and then the vineyard, or the other way round": either order
    (r' (?:, )?or (?:the other way (?:round|around)|vice versa|the reverse|the opposite way|the other order)'
     r'(?: if (?:that is|it is) (?:easier|quicker|better|simpler)| if you (?:prefer|like|want))?(?= [,.;!?] '
     r'|$)',
     ' , in any order '),
    # "do the usual round - gallery 3, gallery 4, then the print room": the round is the list after it
    (r' do (?:the|your|my|our) (?:usual |normal |regular |standard |nightly |night |evening |morning |'
     r'daily )?(?:round|rounds|route|circuit|loop|tour|patrol|walk) (?:, |: )'
     r'(?=[^,.;!?]*(?: , | then | and ))', ' visit '),
    # "send it up to the clifftop" first thing, nothing named before "it": the drone itself, flown there
    (r'^ send it (?:(?:up|over|out|down|across) )?(?:to|towards) (?=(?:the|my|your|our) )', ' fly to '),
    # "beach huts, pier, harbour wall... do that lot backwards": the goals listed ("the lot" alone may
    # be a parking lot)
    (r' (?P<v>do|visit|hit|cover|check) (?:all )?(?:that|this) lot ', r' \g<v> them '),
    # "actually either the copier or the printer is fine": a choice of where to go, said as a permission
    (rf'(^ | [.;!?] | actually (?:, )?| no (?:, )?)either (?P<x>(?:the )?{_NAME}) or (?P<y>(?:the )?{_NAME}) '
     r'(?:is|are|would be|will be) (?:fine|ok|okay|good|alright)(?: too| as well)?(?= [.;!?] |\s*$)',
     r'\1 go to either \g<x> or \g<y> '),
    (r' do (?=(?:them|those|these|all of them|all three|all four) )', ' visit '),
    # the order left to the robot, said as a remark (before list positions: "which one first" is none)
    (r' (?:it )?(?:does not|do not|will not) (?:matter|care|mind)(?: to me)? which(?: one| of them| order)?'
     r'(?: (?:comes|goes|you do|you visit|is done|gets done|you hit))? first ', ' in any order '),
    (r' (?:in )?(?:whichever|whatever|either) order(?: (?:suits you|you like|you want|you prefer|is easier|'
     r'works(?: for you| best)?|you choose|is fine|is (?:quicker|quickest|faster|fastest|shorter|shortest|'
     r'best|closer|simpler|more efficient|most efficient)|makes (?:more )?sense))? ', ' in any order '),
    # "go to a . when you are done there , head to b" -> "go to a . then head to b"
    (rf'(^ | [,.;!?] | and ){_DONE} (?:, )?', r'\1 then '),
    (r' (?:while|when) (?:heading|going|travelling|traveling|flying|driving|walking|moving) '
     r'(?=from |between )',
     ' on the way '),
    (r' on the (?:leg|stretch|part|bit|section|segment|trip|journey|flight|drive|walk) (?=from |between )',
     ' on the way '),
    (r' on the way back (?=from )', ' on the way '),
    (r' on the (?:return leg|return trip|return journey|return flight|trip back|flight back|way back)'
     r'(?= [,.;!?] |$)', ' on the way back '),
    (r' from there (?:out|over|down|up|across|on) to ', ' from there to '),
    # "walk from the north gallery down to the south gallery": from X to Y
    (r' (from (?:the|my|your|our) (?:[a-z0-9_]+ ){0,3}?[a-z0-9_]+) (?:out|over|down|up|across|along|round|'
     r'around|back) to (?=(?:the|my|your|our) )', r' \1 to '),
    # "then do that same walk again", "do the same run again": the route said, again
    (r' do (?:that|the|this) (?:same |very same |exact same )?(?:walk|run|route|trip|loop|circuit|lap|round|'
     r'journey|flight|sweep|pass|drive) (?=again )', ' do that '),
    # "on the way back down to the lawn", "on the way down": the way back, the way
    (r' on the way (?P<b>back )?(?:down|up|over|out) (?=to |towards |keep |stay |avoid |do |never |, )',
     r' on the way \g<b>'),
    (r' on the (?:return leg|return trip|return journey|return flight|trip back|flight back|leg back|'
     r'drive back|'
     r'walk back|way home|journey back) (?=to |towards )', ' on the way back '),
    # "either go to the east gate or the west gate": the choice is of the places
    (r'(^ | [,.;!?] | and | then )either (go to|visit|head to|fly to|drive to|walk to|stop at|head over to) '
     r'(?=(?:the|a|an|my|your|our) [^,.;!?]* or (?:the|a|an|my|your|our) )', r'\1 \2 either '),
    # "go to the hall, but if the hall is busy, go to the lounge instead": one or the other
    (r' , (?:but |or )?if (?:the|that|it)(?: [a-z]+){0,3} (?:is|are|s) (?:too )?(?:busy|closed|locked|'
     r'occupied|full|blocked|taken|unavailable|not available|out of order|shut|crowded|packed) , (?:then )?'
     r'(?:go to|use|try|head to|visit|pick) (?=(?:the|a|an|my|your|our) [^,.;!?]*? instead )', ' or '),
    # "once you're there, don't leave until you've checked the oven": stay there until then
    (r' (?:do not|never) (?:leave|go anywhere|move|budge)(?: (?:from )?(?:there|here|it|that spot))? '
     r'(?=until )', ' stay there '),
    # "before you do that", "before doing so": before the step just named
    (r' (before|after) (?:you (?:go )?do|doing|you have done|having done) (?:that|this|it|so)'
     r'(?: , though| though)?(?= [,.;!?] | )', r' \1 that '),
    # "you're not allowed in the lab until ...": do not go there until then
    (r'(^ | [,.;!?] | and | but )(?:you are |you re )?(?:not|never) (?:allowed|permitted|supposed)'
     r'(?: to (?:go|be|enter|step|visit|approach|set foot))?(?: (?:in|into|inside|to|near|at|on|in to))?'
     r' (?=(?:the|a|an|my|your|our|this|that) [^,.;!?]* (?:until|before) )', r'\1 do not go to '),
    # "you may go to the lab only after the desk": the permission is the order
    (r'(^ | [,.;!?] | and | but )you (?:may|can|could|are allowed to|should|will) (?=(?:go|visit|enter|'
     r'approach|head|fly|drive|walk|land|return|come)[^,.;!?]* only (?:after|once) )', r'\1 '),
    # "only after you've been to the desk may you go to the lab": the same, the order said first
    (r'(^ | [,.;!?] )only (after|once) ((?:you have |you |having )?[a-z]+(?: to| past| by| at| over| on)? '
     r'(?:the|a|an|my|your|our) [^,.;!?]*?) (?:may|can|should|could|will|are) you (?:allowed to )?'
     r'((?:go|visit|enter|approach|head|fly|drive|walk|land|return|come)(?: [a-z]+)? '
     r'(?:the|a|an|my|your|our) [^,.;!?]*?)(?= [,.;!?] | $)', r'\1 \4 only after \3 '),
    # "no sooner than after the bank", "no earlier than": not before
    (r' (?:, )?(?:no|not) (?:sooner|earlier) than (?:after )?', ' but not before '),
    # "don't keep going back to the door": no visit after the first
    (r' (?:do not|never|you should not|you must not) (?:keep|be) (?:going|coming|heading|returning|running|'
     r'popping|flying|driving) back (?:to|into|over to) ((?:the|a|an|my|your|our) [^,.;!?]*?|it|them)'
     r'(?: (?:over and over|again and again|all the time|repeatedly))?(?= [,.;!?] | $)',
     r' do not go to \1 more than once'),
    # "once you have it", "as soon as you've got them": once it is picked up
    (r' (once|as soon as|when|after) you (?:have|have got|got|are holding|hold|have grabbed|grabbed)'
     r' (it|them)(?= , | [.;!?] )', r' \1 you have picked \2 up'),
    # "on two separate trips", "on three different occasions": that many times
    (r' on (one|two|three|four|five|six|seven|eight|nine|ten|\d+) (?:separate |different |distinct )?'
     r'(?:trips|occasions|visits|passes|runs|flights|outings|sorties)(?= [,.;!?] | )', r' \1 times'),
    (r' (two|three|four|five|six|seven|eight|nine|ten|\d+) (?:separate|different|distinct) times ',
     r' \1 times '),
    # "land on the roof or in the pasture": the second place's own preposition
    (r' (on|in|at|to|by|into|onto) (the|a|an|my|your|our) ([^,.;!?]*?) or (?:on|in|at|to|by|into|onto) '
     r'(?=(?:the|a|an|my|your|our) )', r' \1 \2 \3 or '),
    # "go to the cafe beforehand": first
    (r' (?:beforehand|before anything else|before all that)(?= [,.;!?] | $)', ' first '),
    # "keep visiting a and b, forever": the comma says nothing
    (r' , (forever|indefinitely|endlessly|continuously|nonstop|over and over|again and again)'
     r'(?= [,.;!?] | $)', r' \1 '),
    # "the cart, which is right next to the stairs": where the cart is
    (r' , (which|that) (is|are) (?=(?:right |just |directly )?(?:next to|beside|behind|in front of|under|'
     r'underneath|below|beneath|above|over|on top of|near|by|between|left of|right of|to the left of|'
     r'to the right of|opposite|across from|on|in|inside|at) )', r' \1 \2 '),

    (r' (?:from then on|from that point on|from there on|thereafter|from that moment on|after this) ',
     ' after that '),
    (r'(^ | [.;!?] )you (?:may|can|are allowed to|are permitted to|should) only ', r'\1 only '),
    (r' (?:under no circumstances|on no account|at no point|at no time|in neither case|in no case)'
     r'(?: should you| must you| are you to| may you| can you| shall you)? ',
     ' never '),
    # "do not, under any circumstances, go near X", "do not under any circumstances go near X"
    (r' (do not|never|you must not|you should not|you may not) (?:, )?(?:under any circumstances|'
     r'on any account|for any reason|at any point|at any time)(?: ,)? ',
     r' \1 '),
    # "to the glovebox or, alternatively, to the anaerobic chamber": or
    (r' (or|either) , (?:alternatively|otherwise|if you prefer|failing that) , ', r' \1 '),
    (r'(?<!exactly) ((?:one|two|three|four|five|six|seven|eight|nine|ten|\d+) times|once|twice|thrice) '
     r'(?:, )?'
     r'(?:but |and )?no more(?: than that| and no less| , no less)?(?= [,.;!?]|$| $)', r' exactly \1'),
    # "only go in the paddock the once": once
    (r' the once(?= [,.;!?] |$| $)', ' once'),
    (r' (?:have|take|go have|go take|get) a (?:quick |good |close )?(?:look|peek|peep|glance|gander) '
     r'(?:at|in|inside|around|over) ', ' visit '),
    (r' (?:pay|make) a (?:quick )?(?:visit|trip) to ', ' visit '),
    # pictures asked of a place ("get me a shot of the old mill", "I need shots of the spire"): the
    # drone goes there; the picture is nothing to pick up
    (r' (?:(?:get|grab|take|snap|bag|film|shoot) (?:me |us )?|(?:i|we) (?:need|want|would like) )'
     r'(?:a |an |some |a few |a couple of )?(?:(?:quick|nice|good|decent|wide|close|aerial|clean|more) )?'
     r'(?:shot|shots|photo|photos|picture|pictures|pic|pics|snaps|footage|video|videos|clip|clips|image|'
     r'images) of (?=(?:the|my|your|our|that|this|those|these) )', ' go to '),
    (r' (?:check|see|find out|look|make sure|verify|confirm) (?:whether|if) ', ' check '),
    (r' (?:check|see|look) that ', ' check '),
    # "make sure the door is shut": a state to check there (not "make sure you never...")
    (r' (?:make sure|ensure|verify|confirm) (?:that )?(?=(?:the|my|your|our) (?:\w+ ){1,3}(?:is|are) '
     r'(?!never|not|visited|reached|avoided|always)\w)', ' check '),
    # "check the cat is in the laundry room": the place where it is
    (r' check (?:the |my |our |your )(?:\w+ ){1,3}(?:is|are) (?:still )?(?:in|at|inside|on|by|near|next to) '
     r'(?=(?:the|a|an|my|your|our) )', ' check '),
    (r' from there , ', ' after that , '),
    (r'(^ | [,.;!?] | and | then | also )(?:please )?(?:do not forget to|remember to|be sure to|'
     r'try to|you will need to|you will want to) '
     r'(?!not |never |avoid|stay |keep |go near|touch )', r'\1 '),
    # "go to whichever bench is free - the one by the pond or the one by the oak"
    (r' (?:go to |head to |visit |use )?whichever (\w+) (?:is |s )?(?:free|closer|nearer|open|empty|'
     r'available|'
     r'quicker|easier|closest|nearest) (?:, |: )(?=the one )', r' go to either \1 '),
    # "..., but finish at the florist"
    (r' but (?:finish|end) (?:up )?(?:at|by|with|in) (?=(?:the|a|an|my|your|our) )', ' , finally go to '),
    # "the remote that's probably under the cushion": where it is, hedged
    (r' (that is|which is|that are|which are|is|are) (?:probably|maybe|possibly|likely|usually|currently|'
     r'still|normally|hopefully|typically|most likely|likely still|often|sometimes) '
     r'(?=(?:on|under|in|behind|next|by|near|beside|between|above|below|beneath|to the|in front|sitting|'
     r'lying|standing|left|right) )', r' \1 '),
    # "first the tower, next the mast, last the silo": the last stop
    (r'(^ | [,.;!?] | and | then )(?:last|last of all|and last) (?:, )?(?=(?:the|a|an|my|your|our) )',
     r'\1 finally '),
    # "until you have dropped by X": visited it
    (r' (have|you|having|after|until|before|once) '
     r'(?:dropped|popped|swung|stopped|called|looked|checked|come) '
     r'(?:by|in at|in on|into|over to|at) (?=(?:the|a|an|my|your|our) )', r' \1 visited '),
    # "whichever is closer, the a or the b, go there": the choice is the person's reason, not a place
    (r'(^ | [,.;!?] | and | then | to )(go to |head to |visit |to )?whichever (?:one )?'
     r'(?:is |s |of them is |of the two is )?'
     r'(?:closer|closest|nearer|nearest|easier|quicker|faster|more convenient|handier|free|open|emptier|'
     r'less busy|shorter)(?: to (?:reach|get to|get at|access))?(?: to you| for you| of the two)?'
     r'(?: , | : | - )?', r'\1 \2'),
    # "any of the three will do: a, b, or c"
    (r'(^ | [.;!?] )(?:any|either|one|any one) (?:one )?of (?:the |these |those |them )?'
     r'(?:two |three |four |five )?(?:will do|is fine|works|is ok|is okay|would be fine|would do|are fine|'
     r'would work|is good) (?:: |, )?'
     r'(?:go to |visit )?', r'\1 go to any of '),
    (r'(^ | [.;!?] )(?:go to|visit|pick|choose|head to) (?:any|one|either) (?:one )?of (?:these|those|'
     r'the following|them|the two|the three|the four|these places|these spots)(?: places| spots| locations)?'
     r' (?::|,) ', r'\1 go to any of '),
    # "start by going to X", "begin with X", "finish up by dropping by Y": the first and the last step
    (r'(^ | [,.;!?] | and | then )(?:start|begin|kick off|kick things off) (?:off )?(?:by|with) '
     r'(going|heading|visiting|checking|stopping|swinging|flying|driving|walking|making|picking|grabbing|'
     r'bringing|taking|getting|fetching|dropping|popping) ', r'\1 first \2 '),
    (r'(^ | [,.;!?] | and | then )(?:finish|end|wrap) (?:up |off |things up )?(?:by|with) '
     r'(going|heading|visiting|checking|stopping|swinging|flying|driving|walking|making|picking|grabbing|'
     r'bringing|taking|getting|fetching|dropping|popping|landing) ', r'\1 finally \2 '),
    (r'(^ | [,.;!?] | and | then )(?:finish|end|wrap) (?:up |off |things up )?(?:with|at) '
     r'(?=(?:the|a|an|my|your|our) )', r'\1 finally go to '),
    (r' (?:go|come|run|pop) and (?=(?:get|grab|fetch|bring|take|see|check|visit|find|pick|collect) )', ' '),
    (r'(?<! the)(?<! a)(?<! my)(?<! your)(?<! our)(?<! car) (?:wait|stand|sit|park) '
     r'(?:by|near|next to|beside) '
     r'(?=(?:the|a|my|your|our) )', lambda m: m.group(0) if _named_stand(m) else ' go to '),
    # "go and put yourself by the kettle", "position yourself next to the gate": go there
    (r'(?: (?:come|go) and)? (?:put|place|plant|park|position|station|get) yourself '
     r'(?:by|next to|near|beside|at|in|on) (?=(?:the|a|my|your|our) )', ' go to '),
    # "come and wait by me on the sofa", "sit with me in the kitchen": where the person is
    (r'(?: (?:come|go) and)? (?:wait|stand|sit|stay) (?:by|with|next to|beside|near) me (?:on|at|in|by) '
     r'(?=(?:the|my|our) )', ' go to '),
    # "the chair by the window, or if it's taken, the chair by the door": either will do
    (r' (?:, )?or (?:, )?if (?:it|that|this|the \w+|they) (?:is|are|s|happens to be) (?:already )?'
     r'(?:taken|busy|occupied|'
     r'locked|closed|full|blocked|unavailable|not free|not available|in use|out of order|shut|not open|empty)'
     r'(?: , | )', ' or '),
    (r' check there (?:is|are) (?:any |some |a |an )?(?:\w+ ){1,2}(?:in|on|at|inside) '
     r'(?=(?:the|a|an|my|your|our) )', ' check '),
    # "first stop, the bakery. last stop, the florist": the order of the stops
    (r'(^ | [,.;!?] )(first|second|third|fourth|fifth|next) (?:stop|destination|place|location|port of call) '
     r'(?:is |will be )?(?:, |: )?', r'\1 \2 , '),
    (r'(^ | [,.;!?] )(?:last|final) (?:stop|destination|place|location|port of call) '
     r'(?:is |will be )?(?:, |: )?', r'\1 finally '),
    (r' go (?:and )?(?:see|look at|check on|check out|check) ', ' go to '),
    (r' (stay|keep|steer|remain|staying|keeping) (?:well|far|right|way|completely|totally|entirely|'
     r'very far|well and truly) (away|clear|off|out) ', r' \1 \2 '),
    # "your job today is to bring the cup to the sink": the request itself
    (r'(^ | [,.;!?] | and | then )(?:your|the|our|my) (?:first |next |final |last |main |only |new |one )?'
     r'(?:goal|job|task|mission|aim|objective|assignment)(?: for (?:today|tonight|now|the day))?'
     r'(?: today| tonight| now| here)? (?:is|will be) to (?!go to |reach |get to |visit )', r'\1 '),
    (r'(^ | [,.;!?] | and | then )(?:your|the|our|my) (?:first |next |final |last |main |only |new |one )?'
     r'(?:goal|destination|target|aim|objective|end point|'
     r'endpoint|final destination|job|task|mission|stop)(?: for (?:today|tonight|now|the day|this morning))?'
     r'(?: today| tonight| now| this morning| this afternoon| this evening| here)? (?:is|will be|:) '
     r'(?:to (?:go to |reach |get to |visit )?)?',
     r'\1 go to '),
    # "just do the last two. In that order.": the order said as a sentence of its own is the order of the
    # sentence before (alone it was read as nothing)
    (r' [.;!] (?:and |but |just )?(?P<o>(?:strictly )?in '
     r'(?:that|this|the same|the given|exactly that|exactly this) (?:exact |strict |specific )?order|'
     r'in (?:strict )?order|one after the other)(?: ,)?(?: please)?(?= [.;!?] |$)',
     r' , \g<o>'),
    # "And avoid the dog bed. And the fish tank.": a thing added in a sentence of its own after an
    # avoidance is avoided too (it was read as a goal)
    (r'(?P<a>(?:^| [.;!?] )(?:and |but |also )?'
     r'(?:avoid|(?:stay|keep|steer) (?:well )?(?:away|clear) (?:from|of)|'
     r'(?:do not|never) (?:go )?(?:anywhere )?near) [^.;!?]+?) [.;!] and (?:also )?'
     rf'(?P<x>(?:the|my|your|our) {_NOUN}(?: {_NOUN}){{0,3}}?)(?: too| as well)?(?= [.;!?] |$)',
     r'\g<a> , and \g<x>'),
    # "Do not go anywhere near the crib. She's asleep. Anywhere near it.": the avoidance said again
    (r'(?P<a>\b(?:not|never) (?:go |come |get )?anywhere near [^.;!?]*? [.;!?] (?:[^.;!?]* [.;!?] )?)'
     r'(?:anywhere|nowhere) near (?P<x>it|them|that|there)(?= [.;!?] |$)',
     r'\g<a>not anywhere near \g<x>'),
))

# "exactly two times. No more, no less.": the count said exact again (no prohibition of its own)
_NO_MORE_NO_LESS_RE = re.compile(
    r' (?:exactly |precisely )?((?:one|two|three|four|five|six|seven|eight|nine|ten|\d+) times|once|twice|'
    r'thrice) (?:[.,;] )?(?:no|not) more (?:, |and )?(?:no|not) (?:less|fewer)(?: than that)?(?= )')
# "2 times, exactly two": the count said again, exactly
_EXACT_AGAIN_RE = re.compile(
    r' (one|two|three|four|five|six|seven|eight|nine|ten|\d+) times , (?:exactly|precisely) '
    r'(?:one|two|three|four|five|six|seven|eight|nine|ten|\d+|once|twice|thrice)(?: times)?(?= )')

# "exactly once, just the once", "exactly once okay just once": the count said again (with "just"), exactly
_EXACT_SAID_AGAIN_RE = re.compile(
    r' (?:exactly|precisely) (once|twice|thrice|(?:one|two|three|four|five|six|\d+) times) (?:[.,;] )?'
    r'(?:(?:okay|ok|so|yeah|right|yes) (?:[.,;] )?)?(?:just |only )?(?:the )?\1(?: (?:only|please))?(?= )')

_PASS_RE = re.compile(r'(^| )(make|do|take|fly|run|perform|complete|made|done|did|taken|flown|performed|'
                      r'completed|(?:i |we )?(?:want|need)) (one|two|three|four|five|six|seven|'
                      r'eight|nine|ten|\d+|a|an|a single) (?:separate |more |full |complete |quick )?'
                      r'(?:passes|pass|trips|trip|laps|lap|rounds|round|sweeps|sweep|runs|run|loops|loop|'
                      r'flyovers|flyover|visits|visit|circuits|circuit) '
                      r'(?:over|to|by|past|around|round|of|through|across|above|at|along|down|beside)? ?')


_GERUNDS = {'going': 'go', 'heading': 'head', 'visiting': 'visit', 'checking': 'check', 'stopping': 'stop',
            'swinging': 'swing', 'flying': 'fly', 'driving': 'drive', 'walking': 'walk', 'making': 'make',
            'picking': 'pick', 'grabbing': 'grab', 'bringing': 'bring', 'taking': 'take', 'getting': 'get',
            'fetching': 'fetch', 'dropping': 'drop', 'popping': 'pop', 'landing': 'land'}
# "drop by the porch", "pop in at the shop": a visit, not a delivery
_DROP_BY_RE = re.compile(r' (?:drop|pop|duck|nip) (?:by|in at|into|in to|over to) '
                         r'(?=(?:either )?(?:the|a|an|my|your|our) )')
_GERUND_RE = re.compile(r' (first|finally) (' + '|'.join(_GERUNDS) + ') ')


_GROUP_RE = re.compile(r' (?:pick|choose|select|go to|visit|use|head to|take) '
                       r'(?:one of|either of|any of|one among) '
                       r'(?:the|these|those) (?:two|three|four|five) (\w+) (?:, |: )')


def _one_of_group(text: str) -> str:
    """'pick one of the two sinks, the one by the window or the one by the door': go to either sink."""
    m = _GROUP_RE.search(text)
    if m is None:
        return text
    noun = singular(m.group(1))
    end = min((text.find(p, m.end()) for p in (' . ', ' ; ', ' ! ', ' ? ') if text.find(p, m.end()) >= 0),
              default=len(text))
    body = text[m.end():end].replace('the one ', f'the {noun} ').replace(' a one ', f' a {noun} ')
    return text[:m.start()] + ' go to either ' + body + text[end:]


_COLON_RE = re.compile(r'(^ | [.;!?] )(?:pick|choose|select) '
                       r'(?:one|any one|one of them|one of these|either one) : ')
_VERB_COLON_RE = re.compile(r' (avoid|visit|then|never) : ')


# "go by the front door to check it's locked", "visit the tank twice to check": what is done there
_TO_CHECK_RE = re.compile(r'(?<=[a-z]) to check(?= (?:it |(?:the|my|your|our|its|her|his) (?:\w+ ){1,2})'
                          r'(?:is|are) | [,.;!?]|$)')
# Words of a clause that orders or scopes ("not until you've been to X to check ..."): left as said there.
_SCOPING = frozenset({'until', 'till', 'after', 'before', 'once', 'when', 'if', 'unless', 'only', 'while',
                      'whenever', 'not', 'never'})

# "I want to check ...", "we'd like to check ...": a wish, never "and check".
_WISHING = frozenset({'want', 'wanted', 'need', 'needed', 'like', 'love', 'hoping', 'trying'})


def _check_there(text: str) -> str:
    """'go to the door to check it is locked' -> 'go to the door and check it is locked' (a main clause)."""
    out = []
    last = 0
    for m in _TO_CHECK_RE.finditer(text):
        start = max(text.rfind(p, 0, m.start()) for p in (' , ', ' . ', ' ; ', ' ! ', ' ? ', ' : '))
        said = text[max(start, 0):m.start()].split()
        if said[-1:] and said[-1] in _WISHING:
            continue   # "..., I want to check the gun is working": why, not a step of its own
        if not _SCOPING & set(said):
            out.append(text[last:m.start()] + ' and check')
            last = m.end()
    return ''.join(out) + text[last:]


# "you are not to enter that room before ...": the room named before ("the room" is resolved to it)
_THAT_PLACE_RE = re.compile(
    r' (?P<v>enter|visit|approach|avoid|near|into|leave|reach|from|of) (?:that|this) '
    r'(?=(?P<n>room|place|area|spot|location|lab|laboratory|office|building|zone|corridor|bay|ward|site|'
    r'station|space|door) )')


def _that_place(m: 're.Match[str]') -> str:
    # (only a kind of place named before: "go to the den. don't enter that room" stays unread)
    return f' {m.group("v")} the ' if f' {m.group("n")} ' in m.string[:m.start() + 1] else m.group(0)


# Text a sentence holds if any rewrite below may apply to it (else it is returned as it came).
_CUES = (
    ' done', ' finish', ' through', ' ready', ' once ', ' time ', ' look', ' peek', ' peep', ' glance',
    ' gander', ' visit', ' trip', ' see ', ' check', ' whether', ' if ', ' away', ' clear', ' off', ' out',
    ' goal', ' destination', ' target', ' aim', ' objective', ' end', ' job', ' task', ' mission', ' pass',
    ' lap', ' round', ' sweep', ' run', ' loop', ' flyover', ' circuit', ' from ', ' thereafter', ' only ',
    ' no ', ' choose', ' select', ' sure', ' ensure', ' verify', ' confirm', ' pay ', ' what ', ' stop',
    ' place', ' location', ' give ', ' you ', ' and ', ' wait ', ' stand ', ' sit ', ' park ', ' start',
    ' begin', ' kick', ' wrap', ' whichever', ' any ', ' either ', ' one of ', ' drop ', ' duck ', ' nip ',
    ' pop ', ' last ', ' dropped', ' popped', ' swung', ' called', ' come ', ' probably', ' maybe',
    ' possibly', ' likely', ' usually', ' currently', ' still', ' normally', ' hopefully', ' typically',
    ' forget', ' remember', ' try ', ' will need', ' will want', ' should', ' need to', ' have to', ' must',
    ' free', ' often', ' sometimes', ' before ', ' after ', ' allowed', ' permitted', ' supposed', ' sooner',
    ' earlier', ' or ', ' times', ' back ', ' matter', ' care ', ' order', ' do ', ' shot', ' photo', ' pic',
    ' footage', ' video', ' clip', ' image', ' snaps', ' lot ', ' send ')


def paraphrase(tokens: list[str]) -> list[str]:
    """Rewrite paraphrases in ``tokens`` to the phrasing the clause reader knows."""
    text = ' ' + ' '.join(tokens) + ' '
    if 'that' in tokens or 'this' in tokens:
        text = _THAT_PLACE_RE.sub(_that_place, text)
        tokens = text.split()
    if ':' in tokens:
        # "pick one: the den, the hall or the attic" is a choice; "avoid: the ramp, the bins" a list
        text = _VERB_COLON_RE.sub(r' \1 ', _COLON_RE.sub(r'\1 go to one of these : ', text))
        tokens = text.split()
        text = ' ' + ' '.join(tokens) + ' '
    if not any(w in text for w in _CUES):
        return tokens
    text = _one_of_group(text)
    for pattern, repl in _REWRITES:
        text = pattern.sub(repl, text)
    if ' to check' in text:
        text = _check_there(text)
    text = _GERUND_RE.sub(lambda m: f' {m.group(1)} {_GERUNDS[m.group(2)]} ', text)
    text = _DROP_BY_RE.sub(' visit ', text)
    out = text.split()
    out = _passes(out)
    if 'exactly' in out or 'precisely' in out:
        said = _EXACT_AGAIN_RE.sub(r' exactly \1 times', ' ' + ' '.join(out) + ' ')
        out = _EXACT_SAID_AGAIN_RE.sub(r' exactly \1', said).split()
    if 'more' in out and ('less' in out or 'fewer' in out):
        out = _NO_MORE_NO_LESS_RE.sub(r' exactly \1', ' ' + ' '.join(out) + ' ').split()
    return out


# "drone, three passes over the field, then ...": the verb left out at the start of a part
_BARE_PASS_RE = re.compile(r'(^|[,.;:] )(?=(?:two|three|four|five|six|seven|eight|nine|ten|\d+) '
                           r'(?:separate |more |full |complete |quick )?(?:passes|laps|sweeps|circuits|loops|'
                           r'flyovers) (?:over|of|around|round|above|across|through) )')


def _passes(tokens: list[str]) -> list[str]:
    """'make three passes over the farm' -> 'go over the farm three times'."""
    text = _BARE_PASS_RE.sub(r'\1do ', ' '.join(tokens))
    m = _PASS_RE.search(text)
    if m is None:
        return tokens
    before = text[:m.start()].split()
    after = text[m.end():].split()
    np = PhraseParser().parse(after, 0)
    if np is None or after[:1] == ['either']:
        return tokens   # "do a flyover of either the field or the vineyard": a choice (see idioms)
    count = m.group(3)
    # "make a pass over the station": a visit ("once" would read as a count, or open an event)
    times = [] if count in ('a', 'an') else ['once'] if count in ('a single', 'one', '1') else [
        count, 'times']
    if m.group(2) in ('made', 'done', 'did', 'taken', 'flown', 'performed', 'completed'):
        # "once you have made a pass over the substation": once you have visited it
        return before + ['visited'] + after[:np.end] + (times if times != ['once'] else []) + _passes(
            after[np.end:])
    nxt = after[np.end:np.end + 3]
    if times == ['once'] and count != 'one' and nxt and (nxt[0] in ('once', 'twice', 'thrice', 'exactly') or (
            nxt[:2] in (['at', 'least'], ['at', 'most']) or nxt[1:2] == ['times'])):
        times = []   # "make a pass over the field exactly twice": the count that follows counts the passes
    return before + ['go', 'over'] + after[:np.end] + times + _passes(after[np.end:])
