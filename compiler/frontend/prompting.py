"""The model's side of the front end: the motion layer's prompt, the compact answer form and its JSON Schema.

The prompt is built from the reviewed text files in `prompts/` (package
`sovarc.prompts`): an introduction, the dynamic-objects layer of the paper
and the worked examples, each a narrative (`NN_name.txt`) with its full
reading (`NN_name.json`). The environment and road layers (`environment.md`,
`road.md`) are read by rules exactly and so not asked (see `layers`). The
system prompt is the same for every report, so llama.cpp reuses its cached
prefix (saved in ~/.cache/sovarc/prefixes) and only the report's shown
sentences are processed.

The answer form is compact on purpose: per participant its action words then
the numbers of the sentences that state them, and the crash as type, striker,
victim and the impact sentence's number: enum words and small integers, no
free text, short words (most one token). Every token the model generates costs
a quarter of a second on two CPU cores.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from functools import cache
from importlib.resources import files
from typing import Any

from sovarc.compiler.frontend.layers import Shown, motion_layer, states_action, states_impact
from sovarc.compiler.frontend.text import prepare, sentences, up_to_first_impact

# Only the motion layer is asked (see `layers`): environment.md and road.md document the layers the rules read.
PROMPT_FILES = ("system.md", "dynamic.md")
MAX_LANES = 8
# The answer's words for the IR's actions: short (most are one token), so the model generates less.
VEHICLE_WORDS = {
    "follow_lane": "follow",
    "turn_left": "left",
    "turn_right": "right",
    "change_lane_left": "lane_left",
    "change_lane_right": "lane_right",
    "go_across": "across",
    "stop": "stop",
    "u_turn": "u_turn",
    "drive_into": "enter",
    "drive_off": "leave",
    "retrograde": "wrong_way",
}
PEDESTRIAN_WORDS = {"cross": "cross", "walk": "walk"}
# Read by the rules only: no example in the prompt teaches them yet, and a word the examples never show would
# be a guess. Where the rules read one, the settlement keeps it (the model cannot contradict it).
RULES_ONLY = frozenset(("reverse", "parked"))
ACTION_OF = {w: a for a, w in (VEHICLE_WORDS | PEDESTRIAN_WORDS).items()}
VEHICLE_ACTIONS = tuple(VEHICLE_WORDS)
PEDESTRIAN_ACTIONS = tuple(PEDESTRIAN_WORDS)
HEADINGS = ("north", "east", "south", "west", "unknown")
ROAD_KINDS = ("intersection", "t_junction", "straight")
CRASH_TYPES = ("rear_end", "frontal", "side")
MAX_ACTIONS = 5
MAX_CITED = 3  # sentence numbers per fact: enough to point at it, few enough to stay short
MAX_ITEMS = 6  # action words and sentence numbers of one participant together


@dataclass(frozen=True)
class Example:
    name: str
    narrative: str
    answer: dict[str, Any]


def _prompt_dir() -> Any:
    return files("sovarc.prompts")


@cache
def examples() -> tuple[Example, ...]:
    """The worked examples, in file-name order."""
    folder = _prompt_dir() / "examples"
    names = sorted(p.name[: -len(".txt")] for p in folder.iterdir() if p.name.endswith(".txt"))
    return tuple(
        Example(
            name,
            (folder / f"{name}.txt").read_text(encoding="utf-8").strip(),
            json.loads((folder / f"{name}.json").read_text(encoding="utf-8")),
        )
        for name in names
    )


@cache
def system_prompt() -> str:
    """The motion layer's definitions, then the worked examples, each as numbered sentences and answer."""
    parts = [(_prompt_dir() / name).read_text(encoding="utf-8").strip() for name in PROMPT_FILES]
    parts.append("## Worked examples")
    for ex in examples():
        shown = motion_layer(ex.narrative)  # shown as the model will see each report
        parts.append(f"Report:\n{shown.text()}\nAnswer:\n{compact_json(answer_view(ex.answer, shown))}")
    return "\n\n".join(parts) + "\n"


def answer_view(example: dict[str, Any], shown: Shown) -> dict[str, Any]:
    """An example's full reading cut down to the answer form: what the model decides, and where it read it.

    The example files keep the road, headings and lanes too, as documentation of the whole reading; those
    facts are read by rules, so the model is not asked for them. The cited sentences are derived the way the
    cross-check checks them (`layers`): for each participant, the shown sentences about it that state one of
    its actions (the first one about it when it only drives on); for the crash, the impact sentence."""
    out: dict[str, Any] = {}
    for pid, p in example["participants"].items():
        words = VEHICLE_WORDS if pid.startswith("V") else PEDESTRIAN_WORDS
        about = [s for s in shown.sentences if shown.about(s.number, pid)]
        cited = [
            s.number for s in about if any(states_action(s.text, a) for a in p["actions"] if a != "follow_lane")
        ] or [about[0].number]
        out[pid] = [*(words[a] for a in p["actions"]), *cited[:MAX_CITED]]
    c = example["crash"]
    impact = [s.number for s in shown.sentences if states_impact(s.text)][:1] or [shown.sentences[-1].number]
    out["crash"] = [c["type"], c["striker"], c["victim"], *impact]
    return out


def full_schema(ids: list[str]) -> dict[str, Any]:
    """The JSON Schema of a worked example's full reading (for checking the example files)."""
    lane: dict[str, Any] = {"enum": [*range(1, MAX_LANES + 1), "unknown"]}

    def participant(pid: str) -> dict[str, Any]:
        actions = PEDESTRIAN_ACTIONS if pid.startswith("P") else VEHICLE_ACTIONS
        return {
            "type": "object",
            "properties": {
                "heading": {"enum": list(HEADINGS)},
                "lane": lane,
                "actions": {"type": "array", "items": {"enum": list(actions)}, "minItems": 1, "maxItems": 5},
            },
            "required": ["heading", "lane", "actions"],
            "additionalProperties": False,
        }

    crash = {
        "type": "object",
        "properties": {
            "type": {"enum": list(CRASH_TYPES)},
            "striker": {"enum": [*ids, "unknown"]},
            "victim": {"enum": [*ids, "unknown"]},
        },
        "required": ["type", "striker", "victim"],
        "additionalProperties": False,
    }
    people = {"type": "object", "properties": {pid: participant(pid) for pid in ids}, "required": list(ids)}
    return {
        "type": "object",
        "properties": {"road": {"enum": list(ROAD_KINDS)}, "lanes": lane, "participants": people, "crash": crash},
        "required": ["road", "lanes", "participants", "crash"],
    }


def compact_json(value: object) -> str:
    """JSON on one line with the spacing the model is shown (and the grammar allows)."""
    return json.dumps(value, ensure_ascii=False, separators=(",", ":"))


def prepared_narrative(text: str) -> str:
    """The pre-processing step: each participant under one name (V1, P1), the narrative up to the first impact."""
    return " ".join(up_to_first_impact(sentences(prepare(text))))


def user_prompt(shown: Shown, ids: list[str]) -> str:
    return f"Report:\n{shown.text()}\nParticipants: {', '.join(ids)}\nAnswer:"


def repair_prompt(shown: Shown, ids: list[str], previous: str, problems: list[str]) -> str:
    """The report again, the last answer and what is wrong with it."""
    listed = "\n".join(f"- {p}" for p in problems)
    return (
        f"{user_prompt(shown, ids)}\n{previous}\n\n"
        f"That answer is not valid:\n{listed}\nAnswer again for the same report, fixing these problems.\nAnswer:"
    )


def answer_schema(ids: list[str], numbers: list[int]) -> dict[str, Any]:
    """The JSON Schema of the compact answer for a report with these participant ids, whose shown sentences
    have these numbers: per participant its action words then the numbers of the sentences it read them
    from; for the crash its type, striker and victim, then the impact sentence's number. Words and numbers
    only. Draft 7 (the tuple form), the JSON Schema llama.cpp's grammar converter reads as meant."""
    cited = {"enum": list(numbers)}

    def participant(pid: str) -> dict[str, Any]:
        words = PEDESTRIAN_WORDS if pid.startswith("P") else VEHICLE_WORDS
        return {
            "type": "array",
            "items": {"anyOf": [{"enum": list(words.values())}, cited]},
            "minItems": 2,
            "maxItems": MAX_ITEMS,
        }

    who = {"enum": [*ids, "unknown"]}
    # A tuple in the draft-07 form (`items` as a list): llama.cpp's grammar converter ignores `prefixItems`
    # beside `items` and let the model write numbers in place of the type.
    crash = {"type": "array", "items": [{"enum": list(CRASH_TYPES)}, who, who, cited], "minItems": 4, "maxItems": 4}
    return {
        "type": "object",
        "properties": {**{pid: participant(pid) for pid in ids}, "crash": crash},
        "required": [*ids, "crash"],
        "additionalProperties": False,
    }


def answer_budget(ids: list[str]) -> int:
    """max_tokens for an answer: enough for the longest valid one, so a cut-off means garbage."""
    return 30 + 30 * len(ids)
