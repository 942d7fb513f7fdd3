"""The real osm-trajectories data (skipped when ../shared/datasets is absent): reading and the test split."""
from pathlib import Path

import pytest

from ltl_instruct.core.language.learned.data import load_city, split_train_test
from ltl_instruct.core.spec import parse_formula

DATA = Path(__file__).resolve().parents[1].parent / 'shared' / 'datasets' / 'osm-trajectories'
pytestmark = pytest.mark.skipif(not (DATA / 'maps').is_dir(), reason='shared datasets not present')


@pytest.mark.parametrize('city', ['atlanta', 'providence'])
def test_city_reads_and_splits_by_trajectory(city):
    data = load_city(str(DATA), city)
    assert len(data.demonstrations) > 1000 and data.skipped_rows > 0
    train, test = split_train_test(data)
    assert len({d.path for d in test}) == 100
    assert not {d.path for d in train} & {d.path for d in test}
    assert len(train) + len(test) == len(data.demonstrations)
    lmap = data.landmark_map(train)
    assert len(set(lmap.props)) == lmap.num_landmarks
    for p in lmap.props:
        assert parse_formula(f'F {p}') == parse_formula(f'F near[{p}]')
    # every training step is an edge of the map graph
    assert all(tuple(sorted(e)) in lmap.edges for d in train for e in zip(d.path, d.path[1:]))
