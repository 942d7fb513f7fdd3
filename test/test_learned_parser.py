"""The learned parser on a tiny synthetic city: beam search, reward, planning, training, save/load, CLI."""
import json

import numpy as np
import pytest
import torch

from ltl_instruct.cli import main as cli_main
from ltl_instruct.core.errors import ErrorCode, InvalidInputError, LtlInstructError, PlanningError
from ltl_instruct.core.language.base import Translator
from ltl_instruct.core.language.learned import load_translator
from ltl_instruct.core.language.learned.bundle import ModelLoadError, ParserBundle
from ltl_instruct.core.language.learned.data import Demonstration, load_city, split_train_test
from ltl_instruct.core.language.learned.evaluation import PathScores, edit_distance, evaluate
from ltl_instruct.core.language.learned.model import (
    GoalBaseline, ParserConfig, WordVocabulary, pad_batch, tokenize,
)
from ltl_instruct.core.language.learned.planning import plan_on_landmarks
from ltl_instruct.core.language.learned.programs import OutputVocabulary, is_valid_program
from ltl_instruct.core.language.learned.training import (
    GOAL_REWARD, RewardCache, TrainingConfig, new_parser, train_baseline, train_parser,
)
from ltl_instruct.core.spec import parse_formula
from learned_synthetic import NAMES, synthetic_demonstrations, synthetic_map, write_dataset

torch.set_num_threads(1)
# landmark ids of the synthetic grid:  4 5 / 2 3 / 0 1  (rows 170 m apart, columns 166 m apart)
CAFE, LIBRARY, HALL, GARDEN, STATION, MUSEUM = range(6)


@pytest.fixture(scope='module')
def lmap():
    return synthetic_map()


@pytest.fixture(scope='module')
def demos():
    return synthetic_demonstrations(120)


@pytest.fixture(scope='module')
def trained(lmap, demos):
    words = WordVocabulary.build([d.instruction for d in demos])
    parser = new_parser(words, OutputVocabulary(lmap.props), ParserConfig(beam=10), seed=1)
    config = TrainingConfig(epochs=8, beam=10, seed=1, learning_rate=3e-3)
    log = train_parser(parser, words, demos, lmap, config)
    baseline = GoalBaseline(words.size, lmap.num_landmarks)
    train_baseline(baseline, words, demos, epochs=30)
    return ParserBundle(lmap, words, parser, baseline, {'city': 'testville'}), log


def test_props_are_snake_case(lmap):
    assert lmap.props == ('blue_cafe', 'old_library', 'city_hall', 'rose_garden', 'train_station',
                          'art_museum')


def test_plan_product_graph_orders_and_avoids(lmap):
    seq = parse_formula('F (city_hall & F art_museum)')
    plan = plan_on_landmarks(lmap, seq, CAFE)
    assert plan.path[0] == CAFE and plan.path[-1] == MUSEUM
    assert HALL in plan.path[:plan.path.index(MUSEUM)]
    avoid = parse_formula('!city_hall U train_station')
    plan = plan_on_landmarks(lmap, avoid, CAFE)
    assert HALL not in plan.path and plan.path[-1] == STATION
    assert plan.length_m == pytest.approx(lmap.path_length(plan.path))
    # stops at the first accepting point: the start itself satisfies 'blue_cafe'
    assert plan_on_landmarks(lmap, parse_formula('blue_cafe'), CAFE).path == (CAFE,)
    with pytest.raises(PlanningError):
        plan_on_landmarks(lmap, parse_formula('F art_museum & G !art_museum'), CAFE)
    with pytest.raises(InvalidInputError):
        plan_on_landmarks(lmap, parse_formula('F nowhere'), CAFE)
    with pytest.raises(InvalidInputError):
        plan_on_landmarks(lmap, seq, 42)


def test_plan_on_a_map_ten_times_the_largest_city_and_its_expansion_limit():
    """160 landmarks (the largest city has 15): graph built once, the plan optimal, the limit typed."""
    import networkx as nx
    from ltl_instruct.core.world.landmarks import build_landmark_map
    rng = np.random.default_rng(3)
    lat_lon = np.column_stack([42.37 + rng.uniform(0, 0.02, 160), -71.12 + rng.uniform(0, 0.03, 160)])
    big = build_landmark_map('bigville', [f'place {i}' for i in range(160)], lat_lon)
    assert big.adjacency is big.adjacency                       # built once per map
    a, b, c = 17, 93, 141
    formula = parse_formula(f'F ({big.props[a]} & F ({big.props[b]} & F {big.props[c]}))')
    plan = plan_on_landmarks(big, formula, 0)
    g = big.graph()
    best = sum(nx.shortest_path_length(g, u, v, weight='weight') for u, v in ((0, a), (a, b), (b, c)))
    assert plan.path[-1] == c and plan.length_m == pytest.approx(best)
    with pytest.raises(LtlInstructError) as e:
        plan_on_landmarks(big, formula, 0, max_expansions=50)
    assert e.value.code is ErrorCode.LIMIT_EXCEEDED


def test_reward_uses_first_acceptance_and_the_plan(lmap):
    vocab = OutputVocabulary(lmap.props)
    cache = RewardCache(vocab, lmap)
    f_op, and_op = vocab.op_id('F'), vocab.op_id('&')
    straight = Demonstration('x', (CAFE, HALL, STATION))
    assert cache.reward((STATION, f_op), straight) == 1.0                       # planned = shortest = demo
    assert cache.reward((HALL, f_op), straight) == 0.0                          # accepted too early
    detour = Demonstration('x', (CAFE, LIBRARY, GARDEN, STATION))               # not the shortest way
    assert cache.reward((STATION, f_op), detour) == GOAL_REWARD                 # right goal, other route
    via = (GARDEN, STATION, f_op, and_op, f_op)                                 # F (garden & F station)
    assert cache.reward(via, detour) in (GOAL_REWARD, 1.0)
    assert cache.reward((MUSEUM, f_op), detour) == 0.0                          # never accepted
    before = cache.misses
    cache.reward((STATION, f_op), detour)
    assert cache.misses == before                                               # cached


def test_beam_search_yields_valid_sorted_programs(trained):
    bundle, _ = trained
    words, lengths = pad_batch([bundle.words.encode(t) for t in ['go to the art museum', 'xyzzy', 'a b c']])
    states, mask = bundle.parser.encode(words, lengths)
    for epsilon in (0.0, 0.5):
        for result in bundle.parser.beam_search(states, mask, beam=20, epsilon=epsilon,
                                                rng=np.random.default_rng(0)):
            assert 1 <= len(result.programs) and (epsilon > 0 or len(result.programs) <= 20)
            assert len(set(result.programs)) == len(result.programs)
            assert all(is_valid_program(bundle.out_vocab, p) for p in result.programs)
            assert all(len(p) <= bundle.parser.config.max_program for p in result.programs)
            assert result.scores == sorted(result.scores, reverse=True)
    # the beam's scores are the log-probabilities the scorer assigns
    result = bundle.parser.beam_search(states[:1], mask[:1], beam=5)[0]
    logp = bundle.parser.program_log_probs(states[:1], mask[:1], [0] * len(result.programs), result.programs)
    assert np.allclose(logp.detach().numpy(), result.scores, atol=1e-4)
    assert np.all(logp.detach().numpy() <= 0)


def test_training_raises_the_reward(trained):
    _, log = trained
    assert log.epochs_run == 8
    # with the copy scores (the default) the search starts among programs over the landmarks
    # named, none rewarded at first on these templates, and finds rewarded ones epoch by epoch
    assert log.mean_reward_per_epoch[-1] > log.mean_reward_per_epoch[0] + 0.05
    assert log.hit_rate_per_epoch[-1] > log.hit_rate_per_epoch[0] + 0.1


def test_evaluation_and_metrics(trained, demos):
    bundle, _ = trained
    result = evaluate(bundle, demos[:20])
    for name in ('model', 'baseline'):
        r = result[name]
        assert r['n'] == 20 and 0 <= r['goal_accuracy'] <= 1 and r['edit_distance'] >= 0
    assert edit_distance([1, 2, 3], [1, 3]) == 1 and edit_distance([], [1, 2]) == 2
    s = PathScores()
    s.add([0, 1, 2], [0, 1, 2])
    s.add([0, 3], [0, 1, 2])
    assert s.goal_accuracy == 0.5 and s.path_accuracy == 0.5
    assert s.precision == pytest.approx(0.75) and s.recall == pytest.approx(2 / 3)


def test_save_load_round_trip_and_translator(trained, tmp_path):
    bundle, _ = trained
    path = str(tmp_path / 'm' / 'testville.pt')
    bundle.save(path)
    translator = load_translator(path)
    assert isinstance(translator, Translator)
    text = 'start at blue cafe and go to city hall then art museum'
    direct = translator.translate(text)
    again = load_translator(path).translate(text)
    assert str(direct.formula) == str(again.formula)
    assert parse_formula(str(direct.formula)) is not None
    assert all(r in bundle.landmark_map.props for r in direct.referents)
    for bad in ('', '   '):
        with pytest.raises(LtlInstructError):
            translator.translate(bad)
    with pytest.raises(LtlInstructError) as e:
        translator.translate('go ' * 2000)
    assert e.value.code == ErrorCode.LIMIT_EXCEEDED


def test_bad_model_files(tmp_path):
    garbage = tmp_path / 'garbage.pt'
    garbage.write_bytes(b'\x00not a model')
    foreign = tmp_path / 'foreign.pt'
    torch.save({'format': 'something else'}, str(foreign))
    for p in (garbage, foreign, tmp_path / 'missing.pt'):
        with pytest.raises(ModelLoadError) as e:
            ParserBundle.load(str(p))
        assert e.value.code == ErrorCode.MODEL_ERROR


def test_dataset_reading_counts_bad_rows_and_splits_by_trajectory(tmp_path):
    write_dataset(str(tmp_path), n=60)
    data = load_city(str(tmp_path), 'testville')
    assert data.skipped_rows == 2 and len(data.demonstrations) == 60
    assert data.names == NAMES
    train, test = split_train_test(data)
    assert len(train) + len(test) == 60 and test
    assert not {d.path for d in train} & {d.path for d in test}
    assert split_train_test(data) == (train, test)                              # fixed
    with pytest.raises(InvalidInputError):
        load_city(str(tmp_path), 'nowhere')
    with pytest.raises(InvalidInputError):
        load_city(str(tmp_path), '../etc')


def test_tokenize():
    words = ['go', 'to', "joe's", 'cafe', 'then', '7', 'eleven']
    assert tokenize("Go to Joe's Cafe, then 7-Eleven!") == words


def test_cli_train_eval(tmp_path, capsys):
    write_dataset(str(tmp_path), n=40)
    model = str(tmp_path / 'testville.pt')
    assert cli_main(['parser', 'train', '--city', 'testville', '--data', str(tmp_path), '--out', model,
                     '--epochs', '2', '--threads', '1', '--quiet']) == 0
    assert 'trained testville' in capsys.readouterr().out
    assert cli_main(['parser', 'eval', '--city', 'testville', '--data', str(tmp_path), '--model', model,
                     '--json', '--threads', '1']) == 0
    result = json.loads(capsys.readouterr().out)
    assert result['city'] == 'testville' and result['model']['n'] == result['test_instructions'] > 0
    assert cli_main(['parser', 'eval', '--city', 'testville', '--data', str(tmp_path), '--model', model]) == 0
    assert 'baseline' in capsys.readouterr().out
    # restarts: four seeds probed by successive halving (one epoch, the better two one more),
    # the best by training reward trained on; the kept run's log goes on from its probes
    assert cli_main(['parser', 'train', '--city', 'testville', '--data', str(tmp_path), '--out', model,
                     '--epochs', '3', '--threads', '1', '--quiet', '--restarts', '4',
                     '--probe-epochs', '1']) == 0
    info = ParserBundle.load(model).info
    first, second = info['probe_rounds']
    assert len(first) == 4 and len(second) == 2
    kept = sorted(first, key=lambda k: (-first[k], int(k)))[:2]
    assert sorted(second) == sorted(kept)
    best = min(second, key=lambda k: (-second[k], int(k)))
    assert info['chosen_seed'] == int(best)
    log = info['training']
    assert log['epochs_run'] == 3 and log['mean_reward_per_epoch'][1] == second[best]
    for bad in (['--restarts', '0'], ['--probe-epochs', '-1']):
        assert cli_main(['parser', 'train', '--city', 'testville', '--data', str(tmp_path), '--out', model,
                         *bad]) == 2
    # bad input: exit status 2 with a typed error
    assert cli_main(['parser', 'eval', '--city', 'nowhere', '--data', str(tmp_path), '--model', model]) == 2
    assert cli_main(['parser', 'eval', '--city', 'testville', '--data', str(tmp_path),
                     '--model', str(tmp_path / 'none.pt')]) == 2
    assert cli_main(['parser', 'train', '--city', 'testville', '--data', str(tmp_path), '--out', model,
                     '--epochs', '0']) == 2
    assert 'MODEL_ERROR' in capsys.readouterr().err


def test_seed_probing_stops_at_its_share_of_the_time_budget(tmp_path, monkeypatch):
    """Out of probing time after the first round: the best seed so far is kept and trained on."""
    from ltl_instruct.core.language.learned import city as city_module
    write_dataset(str(tmp_path), n=40)
    monkeypatch.setattr(city_module, 'PROBE_SHARE', 0.0)   # the probe deadline has passed at once
    bundle = city_module.train_city(str(tmp_path), 'testville', TrainingConfig(epochs=2, beam=5),
                                    ParserConfig(beam=5), threads=1, restarts=4, probe_epochs=1)
    info = bundle.info
    assert len(info['probe_rounds']) == 1 and len(info['probe_rounds'][0]) == 4   # no second round
    assert info['chosen_seed'] == 0          # no seed trained in time: all tie at 0, the first kept
    assert info['training']['epochs_run'] == 2   # the chosen one still gets the rest of the budget
