"""How fast and how big the embedded model is: join+verify, model load, tokens/s, peak memory.

The request is the front end's own: the layered system prompt (its processed state is restored from
`~/.cache/sovarc/prefixes` after the first run) and the compact answer form.

Run on demand: `python benchmarks/bench_embedded.py [--cache-dir DIR] [--threads N]`.
With a fresh `--cache-dir` the first figure is a cold join; otherwise it is the
marker check. Prints figures; asserts nothing beyond the answer validating.
"""

from __future__ import annotations

import argparse
import json
import resource
import time
from pathlib import Path

import jsonschema
from sovarc.compiler.frontend import prompting
from sovarc.compiler.frontend.providers.embedded import EmbeddedProvider
from sovarc.compiler.frontend.providers.model_file import ensure_model_file

NARRATIVE = (
    "The crash happened on a two-lane rural road with one lane in each direction. The posted speed limit was "
    "55 mph. It was raining and dark, with no street lights. V1, a 2014 Honda Civic, was traveling northbound "
    "at about 50 mph. V2, a 2009 Chevrolet Silverado, was traveling southbound behind a slow tractor. The driver "
    "of V2 crossed the double yellow line to pass the tractor and entered the northbound lane. The driver of V1 "
    "braked and steered right but could not avoid V2. The front of V1 struck the front of V2 in the northbound "
    "lane. Both drivers were transported to a hospital with injuries."
)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--cache-dir", type=Path, default=None)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--max-tokens", type=int, default=1024)
    args = parser.parse_args()

    start = time.perf_counter()
    model_path = ensure_model_file(args.cache_dir)
    print(f"model file ready:     {time.perf_counter() - start:8.2f} s  ({model_path})")

    ids = ["V1", "V2"]
    schema = prompting.answer_schema(ids)
    system = prompting.system_prompt()
    user = prompting.user_prompt(prompting.prepared_narrative(NARRATIVE), ids)
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
