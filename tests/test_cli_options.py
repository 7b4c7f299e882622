"""Every command's options are documented: help text everywhere, and the default named where there is one."""

from __future__ import annotations

import argparse

from nl2hltl2plan.cli.main import build_parser


def _parsers(parser: argparse.ArgumentParser, prog: str = "nl2hltl2plan"):
    yield prog, parser
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for name, sub in action.choices.items():
                yield from _parsers(sub, f"{prog} {name}")


def test_every_option_has_help_and_names_its_default() -> None:
    problems = []
    for prog, parser in _parsers(build_parser()):
        for a in parser._actions:
            if isinstance(a, argparse._HelpAction | argparse._VersionAction | argparse._SubParsersAction):
                continue
            if not a.help:
                problems.append(f"{prog} {a.dest}: no help")
            elif a.option_strings and a.default not in (None, False, argparse.SUPPRESS) and not a.required:
                if "default" not in a.help.lower():
                    problems.append(
                        f"{prog} {a.option_strings[0]}: help does not name its default {a.default!r}"
                    )
    assert not problems, "\n".join(problems)


def test_output_folders_and_files_are_dash_o_everywhere() -> None:
    for prog, parser in _parsers(build_parser()):
        for a in parser._actions:
            if a.dest in ("out", "output"):
                assert "-o" in a.option_strings and "--out" in a.option_strings, prog


def test_plurals_choices_are_the_settings_the_pipeline_takes() -> None:
    """`plan --plurals` and `bench alfred --plurals` offer what `PipelineOptions.plurals` and the web request
    take: one definition (`domain.plurals.Plurals`), so a new setting cannot be missing from one of them."""
    from typing import get_args, get_type_hints

    from nl2hltl2plan.pipeline import PipelineOptions
    from nl2hltl2plan.web.requests import PlanRequest

    settings = get_args(get_type_hints(PipelineOptions)["plurals"])
    assert settings == ("ask", "two")
    assert get_args(get_type_hints(PlanRequest)["plurals"]) == settings
    offered = {
        prog: tuple(a.choices)
        for prog, parser in _parsers(build_parser())
        for a in parser._actions
        if a.dest == "plurals"
    }
    assert {"nl2hltl2plan plan", "nl2hltl2plan bench alfred"} <= set(offered), offered
    assert set(offered.values()) == {settings}, offered
