#!/usr/bin/env python3
"""Runs examples/python/fog_box_budgets.ipynb headless (nbclient, a python3
kernel) from its own folder, as a user opening it there would, at 4x4 pixels:
every cell must run, the four budgets print their relMSE and no cell writes a
warning. Exits 77 (ctest's skip) without python3-nbconvert/nbclient or
python3-ipykernel; both are optional dependencies (tools/install-deps.sh).

    run_notebook.py SOURCE_DIR
"""
import os
import sys
import tempfile
from pathlib import Path

SKIP = 77


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    try:
        import nbformat
        from nbclient import NotebookClient
        from jupyter_client.kernelspec import KernelSpecManager, NoSuchKernel
    except ImportError as error:
        print(f"skipped: {error} (install python3-nbconvert)")
        return SKIP
    try:
        KernelSpecManager().get_kernel_spec("python3")
    except NoSuchKernel:
        print("skipped: no python3 Jupyter kernel (install python3-ipykernel)")
        return SKIP
    folder = Path(sys.argv[1]) / "examples" / "python"
    notebook = nbformat.read(folder / "fog_box_budgets.ipynb", as_version=4)
    os.environ["FEMTO_EXAMPLE_RESOLUTION"] = "4"
    os.environ["MPLBACKEND"] = "Agg"
    os.environ["PYDEVD_DISABLE_FILE_VALIDATION"] = "1"  # the kernel's debugger notice is not femto's
    # femto's C++ warnings go to the kernel's own stderr (inherited), not to
    # cell outputs: catch it in a file for the duration of the run.
    with tempfile.TemporaryFile(mode="w+") as kernel_stderr:
        saved = os.dup(2)
        os.dup2(kernel_stderr.fileno(), 2)
        try:
            NotebookClient(notebook, timeout=100, kernel_name="python3",
                           resources={"metadata": {"path": str(folder)}}).execute()
        finally:
            os.dup2(saved, 2)
            os.close(saved)
        kernel_stderr.seek(0)
        stderr = kernel_stderr.read()
    sys.stderr.write(stderr)
    stdout = ""
    for cell in notebook.cells:
        for output in cell.get("outputs", []):
            if output.get("output_type") == "stream":
                if output["name"] == "stderr":
                    stderr += output["text"]
                else:
                    stdout += output["text"]
    failures = []
    if stdout.count("relMSE") != 4:
        failures.append(f"expected four relMSE lines, got:\n{stdout}")
    warnings = [line for line in stderr.splitlines() if "warning: " in line and "Debugger warning" not in line]
    if warnings:
        failures.append(f"the notebook printed warnings:\n" + "\n".join(warnings) + "")
    for failure in failures:
        print("FAIL:", failure)
    if not failures:
        print(f"ran {sum(c.cell_type == 'code' for c in notebook.cells)} cells from {folder}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
