"""LLM translator against a local OpenAI-compatible server started by the test, with scripted answers."""
from __future__ import annotations

import json
import threading
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from typing import Any, Iterator, Sequence

import numpy as np
import pytest

from ltl_instruct.core.errors import ErrorCode, TranslationError
from ltl_instruct.core.language import make_translator
from ltl_instruct.core.language.llm import (
    ExamplePool, LlmTranslator, PoolExample, extract_formula_text, load_pool,
)


def bag_of_words(texts: Sequence[str]) -> np.ndarray:
    """A cheap embedding for the selection logic: hashed bag of words, shape (N, 64)."""
    out = np.zeros((len(texts), 64))
    for i, t in enumerate(texts):
        for w in t.lower().replace(',', ' ').replace('.', ' ').split():
            out[i, sum(map(ord, w)) % 64] += 1.0
    return out


class Script:
    """Answers to hand out in order; records the requests."""

    def __init__(self) -> None:
        self.answers: list[Any] = []
        self.requests: list[dict[str, Any]] = []


@pytest.fixture()
def server() -> Iterator[tuple[str, Script]]:
    script = Script()

    class Handler(BaseHTTPRequestHandler):
        def log_message(self, *args: Any) -> None:
            pass

        def do_POST(self) -> None:  # noqa: N802 (http.server's name)
            length = int(self.headers.get('Content-Length', 0))
            body = json.loads(self.rfile.read(length))
            script.requests.append({'path': self.path, 'body': body,
                                    'auth': self.headers.get('Authorization')})
            answer = script.answers.pop(0) if script.answers else 'F near[nothing_scripted]'
            if isinstance(answer, tuple) and answer[0] == 'sleep':
                threading.Event().wait(answer[1])
                answer = answer[2]
            if isinstance(answer, tuple) and answer[0] == 'status':
                self.send_response(answer[1])
                self.end_headers()
                return
            if isinstance(answer, tuple) and answer[0] == 'raw':
                payload = answer[1].encode()
            else:
                message = {'role': 'assistant', 'content': answer}
                payload = json.dumps({'choices': [{'message': message}]}).encode()
            self.send_response(200)
            self.send_header('Content-Type', 'application/json')
            self.send_header('Content-Length', str(len(payload)))
            self.end_headers()
            try:
                self.wfile.write(payload)
            except OSError:  # the client gave up (the timeout test)
                pass

    httpd = ThreadingHTTPServer(('127.0.0.1', 0), Handler)
    thread = threading.Thread(target=httpd.serve_forever, daemon=True)
    thread.start()
    try:
        yield f'http://127.0.0.1:{httpd.server_address[1]}/v1', script
    finally:
        httpd.shutdown()
        httpd.server_close()


def make(url: str, **kw: Any) -> LlmTranslator:
    opts: dict[str, Any] = dict(base_url=url, model='scripted', api_key='k3y', embed=bag_of_words, k=3,
                                retries=2, timeout_s=5.0)
    opts.update(kw)
    return LlmTranslator(**opts)


def test_two_stages_with_examples_and_key(server: tuple[str, Script]) -> None:
    url, script = server
    script.answers = ['F (mug & F sink)', 'Formula: F (near[mug] & F near[sink])']
    t = make(url).translate('go to the mug and then the sink')
    assert str(t.formula) == 'F (near[mug] & F near[sink])'
    assert t.backend == 'llm' and t.extra['ltl'] == 'F (mug & F sink)'
    assert len(script.requests) == 2
    first = script.requests[0]
    assert first['path'] == '/v1/chat/completions' and first['auth'] == 'Bearer k3y'
    msgs = first['body']['messages']
    assert msgs[0]['role'] == 'system' and msgs[-1]['content'] == 'go to the mug and then the sink'
    assert len(msgs) == 1 + 2 * 3 + 1   # system, K example pairs, the question
    assert 'LTL: F (mug & F sink)' in script.requests[1]['body']['messages'][-1]['content']


def test_malformed_answer_is_reasked_with_the_error(server: tuple[str, Script]) -> None:
    url, script = server
    script.answers = ['F (a & ', 'F a', 'near[x] &&& oops', 'jump[x]', '```\nF near[box::isbelow(desk)]\n```']
    t = make(url).translate('find the box under the desk')
    assert str(t.formula) == 'F near[box::isbelow(desk)]'
    assert t.extra['retries'] == 3
    reask = script.requests[1]['body']['messages']
    assert reask[-2] == {'role': 'assistant', 'content': 'F (a & '}
    assert 'not valid' in reask[-1]['content']


def test_bounded_retries_then_a_clear_error(server: tuple[str, Script]) -> None:
    url, script = server
    script.answers = ['F a', 'nonsense ((', 'still (( nonsense', 'more ((']
    with pytest.raises(TranslationError) as e:
        make(url, retries=2).translate('go to the door')
    assert e.value.code == ErrorCode.TRANSLATION_ERROR and '3 tries' in e.value.message
    assert len(script.requests) == 4


@pytest.mark.parametrize('answer,code', [
    (('raw', 'this is not json'), ErrorCode.MODEL_ERROR),
    (('raw', '{"choices": []}'), ErrorCode.MODEL_ERROR),
    (('status', 500), ErrorCode.MODEL_ERROR),
])
def test_broken_endpoint_answers_are_typed_errors(server: tuple[str, Script], answer: Any,
                                                  code: ErrorCode) -> None:
    url, script = server
    script.answers = [answer]
    with pytest.raises(TranslationError) as e:
        make(url).translate('go to the door')
    assert e.value.code == code


def test_timeout_is_enforced(server: tuple[str, Script]) -> None:
    url, script = server
    script.answers = [('sleep', 2.0, 'F a')]
    with pytest.raises(TranslationError) as e:
        make(url, timeout_s=0.3, retries=0).translate('go to the door')
    assert e.value.code == ErrorCode.TIMEOUT


def test_unreachable_endpoint() -> None:
    with pytest.raises(TranslationError) as e:
        make('http://127.0.0.1:9/v1', timeout_s=1.0).translate('go to the door')
    assert e.value.code in (ErrorCode.MODEL_ERROR, ErrorCode.TIMEOUT)


def test_correction_is_sent_back_with_the_previous_answer(server: tuple[str, Script]) -> None:
    url, script = server
    script.answers = ['F sofa', 'F near[sofa]', 'F sofa', 'F near[red_sofa]']
    tr = make(url)
    first = tr.translate('go to the sofa')
    second = tr.translate('go to the sofa', correction='I meant the red one', previous=first)
    assert str(second.formula) == 'F near[red_sofa]'
    last = script.requests[-1]['body']['messages']
    assert last[-2] == {'role': 'assistant', 'content': 'F near[sofa]'} and 'red one' in last[-1]['content']


def test_configuration_errors(monkeypatch: pytest.MonkeyPatch) -> None:
    for var in ('LTL_INSTRUCT_LLM_BASE_URL', 'OPENAI_BASE_URL', 'LTL_INSTRUCT_LLM_MODEL', 'OPENAI_MODEL'):
        monkeypatch.delenv(var, raising=False)
    with pytest.raises(TranslationError):
        LlmTranslator(embed=bag_of_words)
    with pytest.raises(TranslationError):
        LlmTranslator(base_url='file:///etc/passwd', model='m', embed=bag_of_words)
    monkeypatch.setenv('LTL_INSTRUCT_LLM_BASE_URL', 'http://127.0.0.1:1/v1')
    monkeypatch.setenv('LTL_INSTRUCT_LLM_MODEL', 'm')
    assert make_translator('llm', embed=bag_of_words).model == 'm'


def test_example_selection_prefers_similar_instructions() -> None:
    pool = [PoolExample('bring the cup to the sink', 'x', 'F near[x]'),
            PoolExample('never go near the stairs', 'x', 'F near[x]'),
            PoolExample('visit the garden exactly once', 'x', 'F near[x]')]
    chosen = ExamplePool(pool, bag_of_words).nearest('avoid the stairs, never go near them', 2)
    assert chosen[-1].instruction == 'never go near the stairs'
    assert len(chosen) == 2


def test_shipped_pool_parses_and_user_pool_errors(tmp_path: Any) -> None:
    assert len(load_pool()) >= 20
    bad = tmp_path / 'pool.jsonl'
    bad.write_text('{"instruction": "x", "formula": "F (("}\n')
    with pytest.raises(TranslationError):
        load_pool(bad)


def test_extract_formula_text() -> None:
    assert extract_formula_text('Sure!\nFormula: F near[a]') == 'F near[a]'
    assert extract_formula_text('```ltl\nG !near[b]\n```') == 'G !near[b]'
    assert extract_formula_text('') == ''


def test_packaged_minilm_model_selects_examples() -> None:
    pytest.importorskip('sentence_transformers')
    from ltl_instruct.core.language.llm import minilm_embedder
    embed = minilm_embedder()
    vecs = embed(['go to the kitchen', 'walk over to the kitchen', 'the weather is nice'])
    assert vecs.shape == (3, 384)
    assert vecs[0] @ vecs[1] > vecs[0] @ vecs[2]
    chosen = ExamplePool(load_pool(), embed).nearest('Could you roll over to the armchair?', 1)
    assert chosen[0].instruction == 'Please drive over to the recliner.'
