"""The packages whose names load on first use (``gazelle/_lazy.py``): every public name resolves, and the
``if TYPE_CHECKING:`` imports (the one list of them) and ``__all__`` name the same things."""

from __future__ import annotations

import importlib
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from gazelle._lazy import lazy_attributes, type_checking_imports

LAZY_PACKAGES = ("gazelle", "gazelle.ros", "gazelle.systems", "gazelle.systems.ros2_control", "gazelle.viewer")


@pytest.mark.parametrize("name", LAZY_PACKAGES)
def test_every_public_name_of_a_lazy_package_resolves_and_is_listed_once(name: str) -> None:
    pkg = importlib.import_module(name)
    assert pkg.__file__ is not None
    table = type_checking_imports(pkg.__file__)
    assert table, f"{name}: no TYPE_CHECKING imports read"
    defined = {n for n in pkg.__all__ if n not in table}
    # what __all__ names beyond the lazy table is defined in the __init__ itself (the ros *_main wrappers)
    assert all(callable(pkg.__dict__.get(n)) for n in defined), defined
    assert set(table) <= set(pkg.__all__), set(table) - set(pkg.__all__)
    for public, (module, attr) in table.items():
        assert getattr(pkg, public) is getattr(importlib.import_module(module, name), attr)


def test_an_unknown_name_is_an_attribute_error_naming_the_package(tmp_path: Path) -> None:
    init = tmp_path / "__init__.py"
    init.write_text("if TYPE_CHECKING:\n    from ._a import b as c\n")
    getattr_ = lazy_attributes("somepkg", str(init))
    with pytest.raises(AttributeError, match="'somepkg' has no attribute 'nope'"):
        getattr_("nope")
    assert type_checking_imports(str(init)) == {"c": ("._a", "b")}


def test_a_client_that_uses_the_bridge_package_for_a_helper_does_not_load_mujoco() -> None:
    code = textwrap.dedent(
        """
        import sys
        from gazelle.systems.ros2_control import load_params
        assert callable(load_params)
        print("mujoco" in sys.modules)
        """
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120, check=True)
    assert out.stdout.strip() == "False", out.stderr
