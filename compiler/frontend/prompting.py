"""The model's side of the front end: the layered prompt, the compact answer form and its JSON Schema.

The prompt is built from the reviewed text files in `prompts/` (package
`sovarc.prompts`): an introduction, one file per layer of the paper
(environment, road network and traffic guidance, dynamic objects) and the
worked examples, each a narrative (`NN_name.txt`) with its answer
(`NN_name.json`). The system prompt is the same for every report, so
llama.cpp reuses its cached prefix and only the report itself is processed.

The answer form is compact on purpose: only facts the model must decide,
enum words and small integers, no free text. The model copies free text
(a full IR schema makes it write out the narrative), and every token costs
time on two CPU cores.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from functools import cache
from importlib.resources import files
from typing import Any

from sovarc.compiler.frontend.text import prepare, sentences, up_to_first_impact

PROMPT_FILES = ("system.md", "environment.md", "road.md", "dynamic.md")
MAX_LANES = 8
VEHICLE_ACTIONS = (
    "follow_lane",
    "turn_left",
    "turn_right",
    "change_lane_left",
    "change_lane_right",
    "go_across",
    "stop",
    "u_turn",
    "drive_into",
    "drive_off",
    "retrograde",
)
PEDESTRIAN_ACTIONS = ("cross", "walk")
HEADINGS = ("north", "east", "south", "west", "unknown")
ROAD_KINDS = ("intersection", "t_junction", "straight")
CRASH_TYPES = ("rear_end", "frontal", "side")
MAX_ACTIONS = 5


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
    """The layers, then the worked examples, each as report and answer."""
    parts = [(_prompt_dir() / name).read_text(encoding="utf-8").strip() for name in PROMPT_FILES]
    parts.append("## Worked examples")
    for ex in examples():
        # shown prepared, as the model will see each report
        parts.append(f"Report:\n{prepared_narrative(ex.narrative)}\nAnswer:\n{compact_json(answer_view(ex.answer))}")
    return "\n\n".join(parts) + "\n"


def answer_view(example: dict[str, Any]) -> dict[str, Any]:
    """An example's full reading cut down to the answer form: what the model decides.

    The example files keep the road, headings and lanes too, as documentation
    of the whole reading; those facts are read by rules, so the model is not
    asked for them (every answer token costs time on two CPU cores, and the
    rules read them more reliably)."""
    people = {pid: {"actions": p["actions"]} for pid, p in example["participants"].items()}
    return {"participants": people, "crash": example["crash"]}


def full_schema(ids: list[str]) -> dict[str, Any]:
    """The JSON Schema of a worked example's full reading (for checking the example files)."""
    schema = answer_schema(ids)
    lane: dict[str, Any] = {"enum": [*range(1, MAX_LANES + 1), "unknown"]}
    for person in schema["properties"]["participants"]["properties"].values():
        person["properties"] = {"heading": {"enum": list(HEADINGS)}, "lane": lane, **person["properties"]}
        person["required"] = ["heading", "lane", "actions"]
    schema["properties"] = {"road": {"enum": list(ROAD_KINDS)}, "lanes": lane, **schema["properties"]}
    schema["required"] = ["road", "lanes", "participants", "crash"]
    return schema


def compact_json(value: object) -> str:
    """JSON on one line with the spacing the model is shown (and the grammar allows)."""
    return json.dumps(value, ensure_ascii=False, separators=(",", ":"))


def prepared_narrative(text: str) -> str:
    """The pre-processing step: each participant under one name (V1, P1), the narrative up to the first impact."""
    return " ".join(up_to_first_impact(sentences(prepare(text))))


def user_prompt(narrative: str, ids: list[str]) -> str:
    return f"Report:\n{narrative}\nParticipants: {', '.join(ids)}\nAnswer:"


def repair_prompt(narrative: str, ids: list[str], previous: str, problems: list[str]) -> str:
    """The report again, the last answer and what is wrong with it."""
    listed = "\n".join(f"- {p}" for p in problems)
    return (
        f"{user_prompt(narrative, ids)}\n{previous}\n\n"
        f"That answer is not valid:\n{listed}\nAnswer again for the same report, fixing these problems.\nAnswer:"
    )


def answer_schema(ids: list[str]) -> dict[str, Any]:
    """The JSON Schema of the compact answer for a report with these participant ids."""

    def participant(pid: str) -> dict[str, Any]:
        actions = PEDESTRIAN_ACTIONS if pid.startswith("P") else VEHICLE_ACTIONS
        return {
            "type": "object",
            "properties": {
                "actions": {
                    "type": "array",
                    "items": {"enum": list(actions)},
                    "minItems": 1,
                    "maxItems": MAX_ACTIONS,
                },
            },
            "required": ["actions"],
            "additionalProperties": False,
        }

    return {
        "type": "object",
        "properties": {
            "participants": {
                "type": "object",
                "properties": {pid: participant(pid) for pid in ids},
                "required": list(ids),
                "additionalProperties": False,
            },
            "crash": {
                "type": "object",
                "properties": {
                    "type": {"enum": list(CRASH_TYPES)},
                    "striker": {"enum": [*ids, "unknown"]},
                    "victim": {"enum": [*ids, "unknown"]},
                },
                "required": ["type", "striker", "victim"],
                "additionalProperties": False,
            },
        },
        "required": ["participants", "crash"],
        "additionalProperties": False,
    }


def answer_budget(ids: list[str]) -> int:
    """max_tokens for an answer: enough for the longest valid one, so a cut-off means garbage."""
    return 40 + 40 * len(ids)
