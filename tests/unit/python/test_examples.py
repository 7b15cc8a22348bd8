"""examples/python: the script runs (at a tiny resolution) and writes its
figure; the notebook is committed without outputs and its code parses."""
import ast
import json
import os
import subprocess
import sys

from conftest import SOURCE_DIR

EXAMPLES = SOURCE_DIR / "examples" / "python"


def test_script_renders_and_plots(tmp_path):
    figure = tmp_path / "budgets.png"
    out = subprocess.run([sys.executable, str(EXAMPLES / "fog_box_budgets.py"), "--resolution", "4", "-o", str(figure)],
                         capture_output=True, text=True, env=dict(os.environ, MPLBACKEND="Agg"), timeout=100)
    assert out.returncode == 0, out.stderr
    assert "warning: " not in out.stderr, out.stderr  # e.g. volumes compared without their time windows
    assert figure.stat().st_size > 0
    # Four renders, each with its relMSE.
    assert out.stdout.count("relMSE") == 4


def test_notebook_is_stripped_and_parses():
    notebook = json.loads((EXAMPLES / "fog_box_budgets.ipynb").read_text())
    code = [c for c in notebook["cells"] if c["cell_type"] == "code"]
    assert code
    for cell in code:
        assert cell["outputs"] == [] and cell["execution_count"] is None
        ast.parse("".join(cell["source"]))
