"""Every route handler and dependency of the API is a coroutine: a plain function would run
in a thread pool that the simulated clock cannot see (clock.py), so a sea trial would stop
being the same every time (and each request would cost a thread hop)."""

from __future__ import annotations

import ast
from pathlib import Path

import usvstation.api

ROUTE_VERBS = {"get", "post", "put", "delete", "patch", "websocket", "api_route"}


def _sync_handlers_and_dependencies(sources: dict[str, str]) -> set[str]:
    """'file: name' of each plain function that is a route handler or is used in a Depends()
    of any of the files."""
    trees = {name: ast.parse(text) for name, text in sources.items()}
    depended = {node.args[0].id for tree in trees.values() for node in ast.walk(tree)
                if isinstance(node, ast.Call) and getattr(node.func, "id", "") == "Depends"
                and node.args and isinstance(node.args[0], ast.Name)}
    found = set()
    for file, tree in trees.items():
        for node in ast.walk(tree):
            if not isinstance(node, ast.FunctionDef):
                continue
            routed = any(isinstance(d, ast.Call) and isinstance(d.func, ast.Attribute)
                         and d.func.attr in ROUTE_VERBS for d in node.decorator_list)
            if routed or node.name in depended:
                found.add(f"{file}: {node.name}")
    return found


def test_the_check_finds_a_plain_function():
    sources = {"a.py": "from fastapi import Depends\nfrom b import dep\nX = Depends(dep)\n",
               "b.py": "def dep(): ...\n@router.get('/x')\ndef handler(): ...\n"}
    assert _sync_handlers_and_dependencies(sources) == {"b.py: dep", "b.py: handler"}


def test_every_route_and_dependency_is_async():
    folder = Path(usvstation.api.__file__).parent
    sources = {p.name: p.read_text(encoding="utf-8") for p in sorted(folder.glob("*.py"))}
    assert _sync_handlers_and_dependencies(sources) == set()
