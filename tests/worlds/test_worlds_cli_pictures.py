import json

import pytest

from nl2hltl2plan.cli.main import main
from nl2hltl2plan.errors import WorldError
from nl2hltl2plan.present.pictures import animate_execution, draw_execution, draw_world
from nl2hltl2plan.worlds import execute
from nl2hltl2plan.worlds.scripted import scripted_plan


def test_world_demo_text(capsys):
    assert main(["world", "demo"]) == 0
    out = capsys.readouterr().out
    assert "world demo (demo): grid 10 x 14 cells of 0.25 m, 132 free cells" in out
    assert "DishwasherLowerRack 1" in out


def test_world_demo_json_run_and_pictures(tmp_path, capsys):
    png = tmp_path / "run.png"
    assert main(["world", "demo", "--json", "--run", "-o", str(png)]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["free_cells"] == 132 and out["objects_by_type"]["Saucer"] == 2
    run = out["run"]
    assert run["ok"] and run["check"]["success"]
    steps = run["check"]["goal_steps"]
    assert max(steps["A"], steps["B"], steps["C"]) < steps["D"] < steps["E"]
    assert png.stat().st_size > 1000


def test_world_map_with_regions(tmp_path, capsys):
    png = tmp_path / "map.png"
    assert main(["world", "demo", "-o", str(png), "--regions", "Fridge", "Plate_0", "--objects"]) == 0
    out = capsys.readouterr().out
    assert "AppleSliced_0" in out and "(appears when sliced)" in out and png.exists()


@pytest.mark.parametrize(
    "argv, message",
    [
        (["world", "demo", "--gif", "x.gif"], "--gif needs --run"),
        (["world", "demo", "-o", "x.png", "--regions", "Sofa"], "no object or type 'Sofa'"),
        (["world", "Kitchen"], "unknown world 'Kitchen'"),
    ],
)
def test_world_errors(argv, message, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert main(argv) == 2
    assert message in capsys.readouterr().err


def test_world_help(capsys):
    assert main(["world", "--help"]) == 0
    assert "--json" in capsys.readouterr().out


def test_draw_functions(demo, tmp_path):
    plan = scripted_plan(
        demo, {0: ((0, 0), ["pickup Mug_0", "put Mug_0 CounterTop_0"]), 1: ((9, 13), ["goto 5 12"])}
    )
    ex = execute(demo, plan)
    draw_world(demo, tmp_path / "w.png", regions=["Fridge_0"])
    draw_execution(ex, tmp_path / "e.png")
    gif = animate_execution(ex, tmp_path / "e.gif", max_frames=6)
    assert all((tmp_path / n).stat().st_size > 1000 for n in ("w.png", "e.png", "e.gif")) and gif.exists()
    with pytest.raises(WorldError):
        draw_world(demo, regions=["Nothing_9"])
