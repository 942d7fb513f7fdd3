"""The learned translator's parts, exercised for real on a small model built here.

The encoder test compares our BERT forward pass with ``transformers.BertModel`` on the
packaged MiniLM weights. The other tests build a small random BERT (same tokenizer), train
tagger and decoder on a few hundred sentences, save the bundle, load it through
``make_translator`` and check what it reads, as a user would.
"""
from __future__ import annotations

import random
import shutil

import pytest
import torch

from ltl_instruct.core.errors import LtlInstructError, TranslationError
from ltl_instruct.core.language import make_translator
from ltl_instruct.core.language.neural import training
from ltl_instruct.core.language.neural.encoder import (
    WordPieces, load_encoder, pad_batch, packaged_model_dir,
)
from ltl_instruct.core.language.neural.examples import Mention, TaggedExample, check_example
from ltl_instruct.core.language.neural.features import (
    TAG_B, TAG_I, TAG_O, mentions_from_tags, piece_tags, spans_from_tags,
)
from ltl_instruct.core.language.neural.grammar import (
    SLOTS, TOKEN_ID, TOKENS, GrammarState, check_prefix, from_prefix, to_prefix,
)
from ltl_instruct.core.language.neural.model import NetConfig, TranslatorNet
from ltl_instruct.core.spec import parse_formula


@pytest.mark.parametrize('text', [
    'F (near[s1] & F near[s2]) & G !near[s3]', 'F (pick[s1] & F release[s1, s2])', '!near[s2] U near[s1]',
    'G (near[s1] -> F near[s2])', 'near[s1] <-> X near[s2]', 'F (near[s1] | near[s2]) & true',
    'near[s1] W (near[s2] R !near[s3])',
])
def test_prefix_round_trip(text):
    f = parse_formula(text)
    tokens = to_prefix(f)
    assert check_prefix(tokens)
    assert from_prefix(tokens) == f


def test_grammar_only_allows_complete_formulas():
    rng = random.Random(3)
    for _ in range(300):
        state, tokens = GrammarState.start(max_len=20), []
        while not state.done:
            tok = rng.choice(state.allowed(n_slots=3))
            tokens.append(TOKENS[tok])
            state = state.push(tok)
        assert len(tokens) <= 20
        assert check_prefix(tokens, 3)
        from_prefix(tokens)            # parses
        assert {t for t in tokens if t in SLOTS} <= {'s1', 's2', 's3'}


def test_slot_positions_need_slots():
    state = GrammarState.start().push(TOKEN_ID['release'])
    # the instruction's two slots, and the things a task implies without naming (the trash can)
    assert state.allowed(2) == [TOKEN_ID['s1'], TOKEN_ID['s2'], TOKEN_ID['trash_can']]
    assert not check_prefix(['release', 's1'])
    assert not check_prefix(['near', 'F'])


def test_check_example_rejects_inconsistent_examples():
    good = TaggedExample('go to the den', 'F near[s1]', (Mention(6, 13, 's1'),), {'s1': 'den'})
    check_example(good)
    with pytest.raises(ValueError):
        check_example(TaggedExample('go to the den', 'F near[s2]', (Mention(6, 13, 's1'),), {'s1': 'den'}))
    with pytest.raises(ValueError):
        check_example(TaggedExample('go to the den', 'F near[s1]', (Mention(6, 40, 's1'),), {'s1': 'den'}))


def test_encoder_matches_transformers_bert():
    transformers = pytest.importorskip('transformers')
    path = packaged_model_dir()
    ours, pieces = load_encoder(path), WordPieces(path)
    theirs = transformers.BertModel.from_pretrained(str(path)).eval()
    ids, mask = pad_batch(pieces.batch(['go to the red sofa behind the pillar', 'hi']))
    with torch.inference_mode():
        a = ours(ids, mask)
        b = theirs(input_ids=ids, attention_mask=mask).last_hidden_state
    assert torch.allclose(a[mask.bool()], b[mask.bool()], atol=1e-4)


def test_tags_and_mentions_round_trip():
    path = packaged_model_dir()
    text = 'go to the red sofa behind the pillar, then the tv'
    pieces = WordPieces(path)(text)
    mentions = (Mention(6, 36, 's1'), Mention(43, 49, 's2'))
    tags, slots = piece_tags(pieces, mentions)
    assert tags.count(TAG_B) == 2 and TAG_I in tags and TAG_O in tags
    assert spans_from_tags(pieces, tags) == [(6, 36), (43, 49)]
    found = mentions_from_tags(text, pieces, tags)
    assert [(m.descriptor, m.slot) for m in found] == [('red_sofa::isbehind(pillar)', 's1'), ('tv', 's2')]
    again = mentions_from_tags('the den, then the den again', WordPieces(path)('the den, then the den again'),
                               piece_tags(WordPieces(path)('the den, then the den again'),
                                          (Mention(0, 7, 's1'), Mention(14, 21, 's1')))[0])
    assert [m.slot for m in again] == ['s1', 's1']


# --- a small model, trained here -------------------------------------------------------------

NAMES = ('kitchen', 'red sofa', 'front door', 'lamp', 'garage', 'blue room', 'desk', 'plant')
PATTERNS = (
    ('go to the {a} then the {b}', 'F (near[s1] & F near[s2])'),
    ('go to the {a} but never the {b}', 'F near[s1] & G !near[s2]'),
    ('bring the {a} to the {b}', 'F (pick[s1] & F release[s1, s2])'),
)


def _examples(n: int, seed: int) -> list[TaggedExample]:
    rng, out = random.Random(seed), []
    for _ in range(n):
        a, b = rng.sample(NAMES, 2)
        pattern, lifted = rng.choice(PATTERNS)
        text = pattern.format(a=a, b=b)
        i = text.index('the ' + a)
        j = text.index('the ' + b, i + 1)
        ex = TaggedExample(text, lifted, (Mention(i, i + 4 + len(a), 's1'), Mention(j, j + 4 + len(b), 's2')),
                           {'s1': a.replace(' ', '_'), 's2': b.replace(' ', '_')}, 'test')
        check_example(ex)
        out.append(ex)
    return out


@pytest.fixture(scope='module')
def small_bundle(tmp_path_factory):
    """A small random BERT (saved by transformers, with the packaged tokenizer) and a translator on it."""
    transformers = pytest.importorskip('transformers')
    torch.manual_seed(0)
    root = tmp_path_factory.mktemp('neural')
    enc_dir = root / 'encoder'
    config = transformers.BertConfig(vocab_size=30522, hidden_size=32, num_hidden_layers=2,
                                     num_attention_heads=2, intermediate_size=64, max_position_embeddings=128)
    transformers.BertModel(config).save_pretrained(str(enc_dir), safe_serialization=True)
    shutil.copy(packaged_model_dir() / 'tokenizer.json', enc_dir / 'tokenizer.json')
    encoder = load_encoder(enc_dir)
    data = training.encode_examples(_examples(240, 0), encoder, WordPieces(enc_dir), log=lambda s: None)
    small = NetConfig(encoder_dim=32, tagger_hidden=32, hidden=64, token_dim=16)
    cfg = training.TrainConfig(epochs=12, batch=16, lr=3e-3, net=small)
    net = TranslatorNet(cfg.net)
    stats = training.fit(net, data, cfg, log=lambda s: None)
    bundle = root / 'bundle'
    training.save_bundle(net, bundle, {'examples': len(data)})
    return enc_dir, bundle, stats


def test_training_lowers_both_losses(small_bundle):
    _, _, stats = small_bundle
    assert stats['tag_loss'] < 0.1 and stats['decoder_loss'] < 0.2


def test_trained_translator_reads_new_combinations(small_bundle):
    enc_dir, bundle, _ = small_bundle
    t = make_translator('neural', model_path=str(bundle), encoder_path=str(enc_dir))
    seen = {ex.text for ex in _examples(240, 0)}
    right = total = 0
    for ex in _examples(60, 1):
        if ex.text in seen:
            continue
        total += 1
        try:
            right += t.translate(ex.text).formula == ex.formula()
        except LtlInstructError:
            pass
    assert total >= 10 and right / total >= 0.8
    r = t.translate('bring the lamp to the desk')
    assert str(r.formula) == 'F (pick[lamp] & F release[lamp, desk])'
    assert 0.0 < r.extra['confidence'] <= 1.0
    assert [m['descriptor'] for m in r.extra['mentions']] == ['lamp', 'desk']


def test_bad_input_and_missing_model_are_typed_errors(small_bundle, tmp_path):
    enc_dir, bundle, _ = small_bundle
    t = make_translator('neural', model_path=str(bundle), encoder_path=str(enc_dir))
    for text in ('', '   ', 'x' * 5000):
        with pytest.raises(TranslationError):
            t.translate(text)
    with pytest.raises(TranslationError) as e:
        make_translator('neural', model_path=str(tmp_path / 'nothing'))
    assert e.value.code.value == 'MODEL_ERROR'


def test_combined_flags_disagreement_and_takes_over_refusals(small_bundle):
    enc_dir, bundle, _ = small_bundle
    from ltl_instruct.core.language.combined import CombinedTranslator
    from ltl_instruct.core.language.neural.translator import NeuralTranslator
    t = CombinedTranslator(str(bundle))
    t.model = NeuralTranslator(bundle, encoder_path=enc_dir)
    agree = t.translate('go to the kitchen then the lamp')
    assert str(agree.formula) == 'F (near[kitchen] & F near[lamp])'
    assert agree.extra['agreement'] is True and not agree.extra['flagged']
    # the rules write a delivery with its approach; the small model without: flagged, both shown
    differ = t.translate('bring the lamp to the desk')
    assert differ.extra['flagged'] and differ.extra['alternatives']
    assert any('learned model' in w for w in differ.extra['unread'])


@pytest.mark.parametrize('words, descriptor', [
    ('the cup from the kitchen', 'cup::isnextto(kitchen)'),
    ('the blanket out of the closet', 'blanket::isnextto(closet)'),
    ('the remote off of the couch', 'remote::isabove(couch)'),
    ('the remote from under the sofa', 'remote::isbelow(sofa)'),
    ('the cup in the kitchen', 'cup'),
    ('my glasses on the nightstand', 'glasses::isabove(nightstand)'),
    ('the kitchen table', 'kitchen_table'),
])
def test_a_mention_says_where_a_thing_is_taken_from_as_the_rules_read_it(words, descriptor):
    # One reading of "from", "out of", "off" and "in" for both translators (phrases.source_relation):
    # a tagged span "the cup from the kitchen" is the cup by the kitchen, never cup_from_kitchen.
    from ltl_instruct.core.language.neural.features import descriptor_of
    assert descriptor_of(words) == descriptor
    rules = make_translator('offline').translate(f'bring {words} to the desk')
    assert rules.referents[0] == descriptor


def test_a_fine_tuned_encoder_travels_in_the_bundle(small_bundle, tmp_path):
    # fine-tuning updates the encoder's layers with the networks; the bundle carries them
    # (encoder.pt), the translator loads them over the packaged encoder, and the embeddings stay
    enc_dir, _, _ = small_bundle
    torch.manual_seed(1)
    encoder, base = load_encoder(enc_dir), load_encoder(enc_dir)
    data = training.piece_examples(_examples(240, 0), WordPieces(enc_dir))
    assert data and all(e.states is None and e.ids is not None for e in data)
    small = NetConfig(encoder_dim=32, tagger_hidden=32, hidden=64, token_dim=16)
    cfg = training.TrainConfig(epochs=8, batch=16, lr=3e-3, encoder_lr=1e-3, net=small)
    net = TranslatorNet(cfg.net)
    stats = training.fit(net, data, cfg, log=lambda s: None, encoder=encoder)
    assert stats['decoder_loss'] < 0.3
    bundle = tmp_path / 'tuned'
    training.save_bundle(net, bundle, {'examples': len(data)}, encoder)
    saved = torch.load(bundle / training.BUNDLE_ENCODER, weights_only=True)
    assert saved and not any(k.startswith(('word.', 'position.', 'token_type.')) for k in saved)
    assert torch.equal(encoder.word.weight, base.word.weight)   # embeddings frozen
    moved = [k for k, v in saved.items() if not torch.allclose(v.float(), base.state_dict()[k], atol=1e-3)]
    assert len(moved) > len(saved) // 2
    t = make_translator('neural', model_path=str(bundle), encoder_path=str(enc_dir))
    for k, v in saved.items():
        assert torch.allclose(t.encoder.state_dict()[k], v.float())
    seen = {ex.text for ex in _examples(240, 0)}
    fresh = [ex for ex in _examples(60, 1) if ex.text not in seen]
    right = sum(t.translate(ex.text).formula == ex.formula() for ex in fresh)
    assert len(fresh) >= 10 and right / len(fresh) >= 0.8
    # a bundle whose encoder layers do not fit the encoder given is a typed error
    torch.save({'layers.0.query.weight': torch.zeros(3, 3)}, bundle / training.BUNDLE_ENCODER)
    with pytest.raises(TranslationError) as e:
        make_translator('neural', model_path=str(bundle), encoder_path=str(enc_dir))
    assert e.value.code.value == 'MODEL_ERROR'
