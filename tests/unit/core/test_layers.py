"""The package's layers: the components and methods do not import the orchestrator above them
(``problem``, ``scene``, ``study``, ``studies``, ``cli``), so that a method can be used, tested
and replaced without the modules that wire it."""
import ast
from pathlib import Path

import viscocontact

PACKAGE = Path(viscocontact.__file__).parent
LOWER = ("methods", "kernels", "contact", "adhesion", "solvers", "rheology", "profiles")
UPPER = {"problem", "scene", "study", "studies", "cli"}


def _imports(path: Path):
    """``(line, dotted module)`` of every import in ``path``, relative ones resolved."""
    parts = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom):
            base = parts[:len(parts) - node.level] if node.level else []
            yield node.lineno, ".".join(base + ([node.module] if node.module else []))
        elif isinstance(node, ast.Import):
            for alias in node.names:
                yield node.lineno, alias.name


def test_no_component_or_method_imports_the_orchestrator():
    up = [f"{path.relative_to(PACKAGE)}:{line} {module}"
          for layer in LOWER for path in sorted((PACKAGE / layer).rglob("*.py"))
          for line, module in _imports(path)
          if module.split(".")[:2][0] == "viscocontact" and len(module.split(".")) > 1
          and module.split(".")[1] in UPPER]
    assert not up, up
