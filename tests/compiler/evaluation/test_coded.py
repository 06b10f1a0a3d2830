"""The coded-variable scorer and the fold split: the mapping from NMVCCS codes to IR facts, and a split that is
fixed, stratified and disjoint."""

from __future__ import annotations

from collections import Counter

from sovarc.compiler.evaluation import coded
from sovarc.compiler.evaluation.folds import FOLDS, fold_of, split
from sovarc.dsl.ir import (
    Action,
    ActionKind,
    Crash,
    CrashType,
    Environment,
    Lighting,
    Participant,
    Road,
    RoadKind,
    Role,
    Scenario,
    Speed,
    SpeedUnit,
    Weather,
)

from tests.conftest import SHARED, requires_shared

A = ActionKind


def _case(**over: tuple[str, ...]) -> coded.Coded:
    base = {
        "weather": ("Clear--No adverse conditions",) * 2,
        "lighting": ("Dark, but lighted",) * 2,
        "speed_limit": ("56", "48"),
        "junction": ("Intersection",) * 2,
        "crash_type": (
            "Turn Into Opposite Directions (Turning Left)",
            "Turn Into Opposite Directions (Going Straight)",
        ),
        "movement": ("Stopped in traffic lane", "Going straight"),
        "event": ("Turning left at intersection", "From crossing street, turning into opposite direction"),
        "lane": ("Lane two", "Lane one (right curb lane)"),
    }
    return coded.Coded("t/0", 2, **{**base, **over})


def _scenario(v1: tuple[A, ...], v2: tuple[A, ...], lane1: int = 2, crash: CrashType = CrashType.SIDE) -> Scenario:
    return Scenario(
        "t_0",
        environment=Environment((Weather.CLEAR,), (Lighting.DARK, Lighting.STREET_LIGHTS)),
        road=Road(RoadKind.T_JUNCTION, 4, Speed(30, SpeedUnit.MPH)),
        participants=(
            Participant("V1", Role.VEHICLE, lane=lane1, actions=tuple(Action(k) for k in v1)),
            Participant("V2", Role.VEHICLE, actions=tuple(Action(k) for k in v2)),
        ),
        crash=Crash(crash, "V2", "V1"),
    )


def test_a_reading_that_fits_the_codes_scores_right_everywhere() -> None:
    got = coded.score(_scenario((A.STOP, A.TURN_LEFT), (A.FOLLOW_LANE,)), _case())
    assert {k: v[0] for k, v in got.items() if v is not None} == dict.fromkeys(coded.ATTRIBUTES, True)
    assert got["RunningLanes"] is not None  # V1's stated lane is scored, V2's unknown lane is not


def test_a_turn_the_codes_need_and_a_turn_they_deny() -> None:
    missed = coded.score(_scenario((A.STOP,), (A.FOLLOW_LANE,)), _case())["DrivingActions"]
    assert missed is not None and not missed[0] and "turn_left" in missed[1]
    extra = coded.score(_scenario((A.STOP, A.TURN_LEFT), (A.FOLLOW_LANE, A.TURN_RIGHT)), _case())["DrivingActions"]
    assert extra is not None and not extra[0]


def test_lateral_move_is_retrograde_and_a_wrong_lane_counts() -> None:
    case = _case(crash_type=("Head-On: Lateral Move (Left/Right)", "Head-On: Lateral Move (Going Straight)"))
    case = coded.Coded(**{**case.__dict__, "movement": ("Negotiating a curve", "Going straight"), "event": ("", "")})
    assert coded.score(_scenario((A.FOLLOW_LANE, A.RETROGRADE), (A.FOLLOW_LANE,)), case)["DrivingActions"] == (True, "")
    got = coded.score(_scenario((A.FOLLOW_LANE,), (A.FOLLOW_LANE,), lane1=1, crash=CrashType.SIDE), case)
    assert got["DrivingActions"] is not None and not got["DrivingActions"][0]
    assert got["RunningLanes"] is not None and not got["RunningLanes"][0]
    assert got["CrashType"] is not None and not got["CrashType"][0]  # head-on is frontal


def test_codes_with_no_ir_counterpart_are_not_scored() -> None:
    case = _case(speed_limit=("No statutory limit",) * 2, junction=("Entrance/exit ramp related",) * 2)
    got = coded.score(_scenario((A.STOP, A.TURN_LEFT), (A.FOLLOW_LANE,)), case)
    assert got["SpeedLimit"] is None and got["CollisionLocation"] is None


@requires_shared
def test_every_report_has_its_codes_and_the_split_is_fixed_and_stratified() -> None:
    data = SHARED / "data" / "nmvccs"
    codes = coded.load(data / "coded_variables.csv")
    reports = {f"{p.parent.name}/{p.stem}" for p in (data / "reports").glob("*/*.txt")}
    assert reports == set(codes)
    folds = fold_of(data / "reports")
    assert len(folds) == 90 and Counter(folds.values()) == dict.fromkeys(range(FOLDS), 30)
    assert Counter(n.split("/")[0] for n, f in folds.items() if f == 0) == {"crossing": 10, "straight": 10, "t": 10}
    dev, held = split(data / "reports")
    assert not set(dev) & set(held) and fold_of(data / "reports") == folds
