"""How fast and how big the embedded model is: join+verify, model load, tokens/s, peak memory.

The request is the front end's own: the layered system prompt (its processed state is restored from
`~/.cache/sovarc/prefixes` after the first run) and the compact answer form.

Run on demand: `python benchmarks/bench_embedded.py [--cache-dir DIR] [--threads N]`.
With a fresh `--cache-dir` the first figure is a cold join; otherwise it is the
marker check. Prints figures; asserts nothing beyond the answer validating.

`--count-tokens DIR` counts instead, with llama.cpp's own tokenizer and no
generation, what the model reads per report (the user prompt after the cached
system prompt) in the motion layer and in the whole narrative up to the first
impact (what it was sent before), and the answer's length in both forms for the
rules' own reading: figures that do not depend on the machine's load.
"""

from __future__ import annotations

import argparse
import json
import resource
import statistics
import time
import urllib.request
from pathlib import Path
from typing import Any

import jsonschema
from sovarc.compiler.frontend import prompting
from sovarc.compiler.frontend.layers import Shown, motion_layer
from sovarc.compiler.frontend.providers.embedded import EmbeddedProvider
from sovarc.compiler.frontend.providers.model_file import ensure_model_file
from sovarc.compiler.frontend.rules import extract
from sovarc.dsl.ir import Action, ActionKind, Scenario

NARRATIVE = (
    "The crash happened on a two-lane rural road with one lane in each direction. The posted speed limit was "
    "55 mph. It was raining and dark, with no street lights. V1, a 2014 Honda Civic, was traveling northbound "
    "at about 50 mph. V2, a 2009 Chevrolet Silverado, was traveling southbound behind a slow tractor. The driver "
    "of V2 crossed the double yellow line to pass the tractor and entered the northbound lane. The driver of V1 "
    "braked and steered right but could not avoid V2. The front of V1 struck the front of V2 in the northbound "
    "lane. Both drivers were transported to a hospital with injuries."
)


def _tokenizer(model_path: Path) -> Any:
    """A token counter: llama.cpp's /tokenize on a small server of the same model."""
    import xllamacpp  # the model extra

    params = xllamacpp.CommonParams()
    params.model.path = str(model_path)
    params.n_ctx = 512
    params.cpuparams.n_threads = 1
    server = xllamacpp.Server(params)

    def count(text: str) -> int:
        request = urllib.request.Request(
            f"{server.listening_address}/tokenize",
            data=json.dumps({"content": text}).encode(),
            headers={"Content-Type": "application/json"},
        )
        return len(json.loads(urllib.request.urlopen(request, timeout=60).read())["tokens"])

    count.server = server  # type: ignore[attr-defined]  # kept alive as long as the counter
    return count


def _old_answer(s: Scenario) -> str:
    """The answer form before the motion layer: full action words, objects, no evidence."""
    people = {p.id: {"actions": [_word(a) for a in p.known_actions] or ["follow_lane"]} for p in s.participants}
    crash = {"type": str(s.crash.type), "striker": str(s.crash.striker), "victim": str(s.crash.victim)}
    return prompting.compact_json({"participants": people, "crash": crash})


def _new_answer(s: Scenario, shown: Shown) -> str:
    out: dict[str, Any] = {}
    for p in s.participants:
        words = prompting.VEHICLE_WORDS if p.id.startswith("V") else prompting.PEDESTRIAN_WORDS
        about = [x.number for x in shown.sentences if shown.about(x.number, p.id)] or shown.numbers()
        actions = [words.get(_word(a), "follow") for a in p.known_actions] or ["follow"]
        out[p.id] = [*actions, *about[:2]]
    out["crash"] = [str(s.crash.type), str(s.crash.striker), str(s.crash.victim), shown.numbers()[-1]]
    return prompting.compact_json(out)


def _word(a: Action) -> str:
    return f"change_lane_{a.to}" if a.kind is ActionKind.CHANGE_LANE else a.kind.value


def count_tokens(folder: Path, model_path: Path) -> None:
    count = _tokenizer(model_path)
    print(f"system prompt (cached prefix): {count(prompting.system_prompt())} tokens")
    rows = []
    for path in sorted(folder.glob("*.txt"), key=lambda p: (len(p.stem), p.stem)):
        text = path.read_text(encoding="utf-8")
        rules = extract(text, "r", path.name)
        ids = [p.id for p in rules.participants]
        if not ids:
            continue
        shown = motion_layer(text)
        old_user = f"Report:\n{prompting.prepared_narrative(text)}\nParticipants: {', '.join(ids)}\nAnswer:"
        rows.append(
            (
                count(text),
                count(old_user),
                count(prompting.user_prompt(shown, ids)),
                count(_old_answer(rules)),
                count(_new_answer(rules, shown)),
            )
        )
    names = ("whole report", "read before (narrative to impact)", "read now (motion layer)")
    names += ("answer before", "answer now (with evidence)")
    print(f"{len(rows)} reports in {folder}; tokens per report, median (p90):")
    for i, name in enumerate(names):
        values = sorted(r[i] for r in rows)
        print(f"  {name:<36} {statistics.median(values):6.0f} ({values[int(0.9 * (len(values) - 1))]})")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--cache-dir", type=Path, default=None)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--max-tokens", type=int, default=1024)
    parser.add_argument("--count-tokens", type=Path, default=None, metavar="DIR", help="count, do not generate")
    args = parser.parse_args()
    if args.count_tokens is not None:
        count_tokens(args.count_tokens, ensure_model_file(args.cache_dir))
        return

    start = time.perf_counter()
    model_path = ensure_model_file(args.cache_dir)
    print(f"model file ready:     {time.perf_counter() - start:8.2f} s  ({model_path})")

    ids = ["V1", "V2"]
    shown = motion_layer(NARRATIVE)
    schema = prompting.answer_schema(ids, shown.numbers())
    system = prompting.system_prompt()
    user = prompting.user_prompt(shown, ids)
    with EmbeddedProvider(model_path, threads=args.threads) as provider:
        start = time.perf_counter()
        provider.load()
        print(f"model load (worker):  {time.perf_counter() - start:8.2f} s  (in worker {provider.load_seconds:.2f} s)")
        start = time.perf_counter()
        text = provider.complete_json(system, user, schema, max_tokens=args.max_tokens)
        wall = time.perf_counter() - start
        timings = (provider.last_response or {}).get("timings", {})
    jsonschema.validate(json.loads(text), schema)
    print(f"answer wall time:     {wall:8.2f} s")
    print(f"prompt:               {timings.get('prompt_n')} tokens at {timings.get('prompt_per_second', 0):.1f} tok/s")
    print(
        f"generation:           {timings.get('predicted_n')} tokens at "
        f"{timings.get('predicted_per_second', 0):.1f} tok/s"
    )
    worker_kib = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    own_kib = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    print(f"peak RSS:             worker {worker_kib / 1024:.0f} MiB, parent {own_kib / 1024:.0f} MiB")
    print("answer:", text)


if __name__ == "__main__":
    main()
