"""The README and docs/ stay honest: the README is short, every relative link resolves (to a file, and an
anchor to a heading of that file), and every `gazelle` and `ros2` command shown in a shell block names a
command that exists.

Each check is also run on a planted page with a broken link, a missing anchor and an unknown command, so
it can be seen to fail.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
import typer.main

from gazelle.cli import app
from gazelle.cli.ros2cli import VERBS

ROOT = Path(__file__).resolve().parents[2]
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
README_MAX_LINES = 300

_LINK = re.compile(r"(?<!!)\[[^\]]*\]\(([^)\s]+)\)")
_FENCE = re.compile(r"^```(\w*)\s*$")
_INLINE_CODE = re.compile(r"`[^`]*`")
# console scripts gazelle installs beside `gazelle` and `ros2` (pyproject's [project.scripts])
_OTHER_SCRIPTS = {"gzserver", "gzclient"}


def _slug(heading: str) -> str:
    """GitHub's anchor for a heading: lower case, punctuation but '-' and '_' dropped, spaces to '-'."""
    text = heading.strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def _anchors(page: Path) -> set[str]:
    anchors: set[str] = set()
    in_code = False
    for line in page.read_text().splitlines():
        if _FENCE.match(line):
            in_code = not in_code
            continue
        if not in_code and line.startswith("#"):
            anchors.add(_slug(line.lstrip("#")))
    return anchors


def broken_links(page: Path) -> list[str]:
    """Each relative link of `page` whose file or heading does not exist, as 'page:line: target'."""
    problems = []
    in_code = False
    for number, line in enumerate(page.read_text().splitlines(), 1):
        if _FENCE.match(line):
            in_code = not in_code
        if in_code:
            continue
        for target in _LINK.findall(_INLINE_CODE.sub("", line)):
            if re.match(r"^[a-z]+:", target):  # http:, https:, mailto:
                continue
            path_part, _, anchor = target.partition("#")
            linked = (page.parent / path_part).resolve() if path_part else page
            if not linked.exists():
                problems.append(f"{page.name}:{number}: {target} (no such file)")
            elif anchor and linked.suffix == ".md" and anchor not in _anchors(linked):
                problems.append(f"{page.name}:{number}: {target} (no such heading)")
    return problems


def shell_commands(page: Path) -> list[tuple[int, list[str]]]:
    """(line, words) of every command in the page's bash blocks, split at '&&', ';' and '|'."""
    commands = []
    fence: str | None = None
    for number, line in enumerate(page.read_text().splitlines(), 1):
        match = _FENCE.match(line)
        if match:
            fence = None if fence is not None else match.group(1)
            continue
        if fence not in ("bash", "sh", "console"):
            continue
        code = line.split(" #", 1)[0].strip()
        for part in re.split(r"&&|;|\|\s", code):
            words = part.strip().rstrip("&").split()
            if words:
                commands.append((number, words))
    return commands


def unknown_commands(page: Path) -> list[str]:
    gazelle_commands = set(typer.main.get_command(app).commands)  # type: ignore[attr-defined]
    problems = []
    for number, words in shell_commands(page):
        tool, verb = words[0], (words[1] if len(words) > 1 else "")
        if tool == "gazelle" and verb not in gazelle_commands and not verb.startswith(("-", ".")):
            problems.append(f"{page.name}:{number}: gazelle {verb}")
        if tool == "ros2" and verb not in VERBS and not verb.startswith("-"):
            problems.append(f"{page.name}:{number}: ros2 {verb}")
    return problems


def test_the_readme_is_short() -> None:
    lines = (ROOT / "README.md").read_text().count("\n")
    assert lines <= README_MAX_LINES, f"README.md has {lines} lines; keep it under {README_MAX_LINES}, details in docs/"


@pytest.mark.parametrize("page", PAGES, ids=lambda p: p.name)
def test_every_relative_link_resolves(page: Path) -> None:
    assert broken_links(page) == []


@pytest.mark.parametrize("page", PAGES, ids=lambda p: p.name)
def test_every_command_shown_exists(page: Path) -> None:
    assert unknown_commands(page) == []


def test_every_docs_page_is_linked_from_the_readme_or_another_page() -> None:
    linked: set[Path] = set()
    for page in PAGES:
        for target in _LINK.findall(page.read_text()):
            if not re.match(r"^[a-z]+:", target):
                linked.add((page.parent / target.partition("#")[0]).resolve())
    orphans = [p.name for p in PAGES[1:] if p.resolve() not in linked]
    assert orphans == []


def test_the_checks_can_fail(tmp_path: Path) -> None:
    (tmp_path / "other.md").write_text("# Other page\n\n## A heading\n")
    page = tmp_path / "page.md"
    page.write_text(
        "# Page\n\n[ok](other.md#a-heading) [gone](missing.md) [bad anchor](other.md#nope)\n"
        "[web](https://example.org/x) `[a-z](_?[a-z])` is code, not a link\n\n```bash\ngazelle sim &\ngazelle teleport x\nros2 topic list && ros2 frobnicate\n```\n"
    )
    assert broken_links(page) == ["page.md:3: missing.md (no such file)", "page.md:3: other.md#nope (no such heading)"]
    assert unknown_commands(page) == ["page.md:8: gazelle teleport", "page.md:9: ros2 frobnicate"]
