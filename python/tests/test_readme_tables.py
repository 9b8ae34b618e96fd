"""The README's variable tables are the FMU's: generated from its model description, they fail this test when
either drifts (`python -m pistonslap.variable_table README.md` regenerates them)."""

from pathlib import Path

import fmpy

from pistonslap.variable_table import BEGIN, END, replaced

README = Path(__file__).resolve().parents[2] / "README.md"


def test_the_readme_tables_are_the_model_descriptions(fmu_file):
    text = README.read_text()
    md = fmpy.read_model_description(fmu_file)
    assert replaced(text, md) == text, "README's variable tables differ from the FMU's: regenerate them"
    section = text[text.index(BEGIN) : text.index(END)]
    for v in md.modelVariables:
        assert f"| `{v.name}` |" in section, v.name
