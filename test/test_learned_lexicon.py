"""The learned parser's name lexicon and copy scores: which words name which landmarks."""
import numpy as np
import pytest
import torch

from ltl_instruct.core.language.learned.bundle import ParserBundle
from ltl_instruct.core.language.learned.lexicon import name_match_matrix, normalise_word
from ltl_instruct.core.language.learned.model import (
    GoalBaseline, ParserConfig, SemanticParser, WordVocabulary, pad_batch, tokenize,
)
from ltl_instruct.core.language.learned.programs import OutputVocabulary
from ltl_instruct.core.language.learned.training import new_parser
from learned_synthetic import NAMES, synthetic_map

torch.set_num_threads(1)
VOCAB = ('<pad>', '<unk>', 'cosi', 'carmas', 'the', 'cafe', 'internatoinal', 'house', 'pizza', 'walk')
MAP_NAMES = ('Così', "Carma's Cafe", 'Bamboo Cafe', 'International House', 'The Varsity Pizza')


def test_normalised_words_drop_accents_apostrophes_and_plural_s():
    assert normalise_word('Così') == 'cosi'
    assert normalise_word("carma's") == normalise_word('carmas') == 'carma'
    assert normalise_word('glass') == 'glass' and normalise_word('bus') == 'bus'
    assert tokenize('Walk to Così') == ['walk', 'to', 'cosi']


def test_name_match_matrix_weights():
    m = name_match_matrix(VOCAB, MAP_NAMES, tokenize)
    row = {w: m[i] for i, w in enumerate(VOCAB)}
    assert m.shape == (len(VOCAB), len(MAP_NAMES)) and m.dtype == np.float32
    assert row['cosi'][0] == pytest.approx(1.0)                 # the whole name, one landmark
    assert row['carmas'][1] == pytest.approx(0.5)               # one of two name words
    assert row['cafe'][1] == row['cafe'][2] == pytest.approx(0.25)  # shared by two names
    assert row['internatoinal'][3] == pytest.approx(0.25)       # a near miss counts half
    assert row['pizza'][4] == pytest.approx(0.5)                # "the" is not a name word
    for w in ('<pad>', '<unk>', 'the', 'walk'):
        assert not row[w].any()
    assert row['house'][3] == pytest.approx(0.5)
    assert np.count_nonzero(m) == 7


def _first_landmark(parser, words, text):
    ids, lengths = pad_batch([words.encode(text)])
    states, mask = parser.encode(ids, lengths)
    return parser.beam_search(states, mask, beam=5)[0].programs[0][0]


def test_untrained_parser_prefers_the_landmark_named():
    lmap = synthetic_map()
    words = WordVocabulary.build(['go to the', 'walk to'] + list(NAMES))
    vocab = OutputVocabulary(lmap.props)
    parser = new_parser(words, vocab, ParserConfig(), seed=3, names=lmap.names)
    for text in ('go to the art museum', 'walk to city hall', 'go to the old library'):
        named = next(i for i, n in enumerate(lmap.names) if n.lower() in text)
        assert _first_landmark(parser, words, text) == named
    plain = new_parser(words, vocab, ParserConfig(lexical_copy=False), seed=3)
    ids, lengths = pad_batch([words.encode('go to the art museum')])
    states, _ = plain.encode(ids, lengths)
    assert states.shape[2] == 2 * plain.config.encoder_hidden     # the original model: no match rows
    assert not hasattr(plain, 'name_match')


def test_match_matrix_shape_is_checked_and_saved(tmp_path):
    lmap = synthetic_map()
    words = WordVocabulary.build(list(NAMES))
    vocab = OutputVocabulary(lmap.props)
    with pytest.raises(ValueError):
        SemanticParser(words.size, vocab, ParserConfig(), np.zeros((2, 2)))
    parser = new_parser(words, vocab, ParserConfig(), names=lmap.names)
    assert parser.name_match.abs().sum() > 0
    bundle = ParserBundle(lmap, words, parser, GoalBaseline(words.size, lmap.num_landmarks), {})
    bundle.save(str(tmp_path / 'm.pt'))
    loaded = ParserBundle.load(str(tmp_path / 'm.pt'))
    assert torch.equal(loaded.parser.name_match, parser.name_match)
