"""Print realsim's import graph between its top-level parts (subpackages and root modules).

    python scripts/import_graph.py            # every edge, one line per part
    python scripts/import_graph.py --runtime  # only what the runtime side (run, view, export) reaches

Read from the source with ``ast`` (imports inside functions count too); nothing is imported.
"""

from __future__ import annotations

import argparse
import ast
from collections import defaultdict
from pathlib import Path

PACKAGE = Path(__file__).resolve().parents[1] / "realsim"
RUNTIME_SIDE = ("runtime", "viewer", "export", "planner", "robot")


def part_of(module: str) -> str | None:
    """``realsim.perception.planes`` -> ``perception``; None outside realsim."""
    parts = module.split(".")
    return parts[1] if parts[0] == "realsim" and len(parts) > 1 else None


def runtime_nodes(tree: ast.AST) -> list[ast.AST]:
    """Every node of ``tree`` except those under ``if TYPE_CHECKING:`` (annotations, not imports that run)."""
    skipped = {id(n) for node in ast.walk(tree) if isinstance(node, ast.If) and "TYPE_CHECKING" in ast.unparse(node.test)
               for child in node.body for n in ast.walk(child)}
    return [n for n in ast.walk(tree) if id(n) not in skipped]


def import_graph() -> dict[str, set[str]]:
    """Part -> the other parts it imports."""
    graph: dict[str, set[str]] = defaultdict(set)
    for path in sorted(PACKAGE.rglob("*.py")):
        rel = path.relative_to(PACKAGE).with_suffix("")
        source = rel.parts[0]
        for node in runtime_nodes(ast.parse(path.read_text())):
            names = [node.module] if isinstance(node, ast.ImportFrom) and node.module else \
                [a.name for a in node.names] if isinstance(node, ast.Import) else []
            for name in names:
                target = part_of(name)
                if target and target != source:
                    graph[source].add(target)
        graph.setdefault(source, set())
    return graph


def reachable(graph: dict[str, set[str]], roots: tuple[str, ...]) -> set[str]:
    """Every part the roots import, directly or not."""
    seen, todo = set(roots), list(roots)
    while todo:
        for nxt in graph.get(todo.pop(), ()):
            if nxt not in seen:
                seen.add(nxt)
                todo.append(nxt)
    return seen


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runtime", action="store_true", help="only the parts the runtime side reaches")
    args = parser.parse_args()
    graph = import_graph()
    shown = reachable(graph, RUNTIME_SIDE) if args.runtime else set(graph)
    for part in sorted(shown):
        print(f"{part:16s} -> {', '.join(sorted(graph[part])) or '(nothing)'}")


if __name__ == "__main__":
    main()
