"""The bad-input corpus (tests/bad/MANIFEST.tsv) through the Python module: every case
whose spec itself is bad must raise the exception matching the CLI's exit code (2:
c2blend.SpecError, 3: c2blend.NumericalError) with the same message fragment, which
names the field. The CLI runs the same corpus (ctest label bad)."""
import os

import pytest

import c2blend

BAD = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "bad")
EXC = {2: c2blend.SpecError, 3: c2blend.NumericalError}


def cases():
    out = []
    with open(os.path.join(BAD, "MANIFEST.tsv")) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            name, scope, _command, code, fragment = line.rstrip("\n").split("\t")
            if scope == "spec":
                out.append(pytest.param(name, int(code), fragment, id=name))
    return out


@pytest.mark.parametrize("name,code,fragment", cases())
def test_bad_spec_raises_like_the_cli(name, code, fragment):
    with pytest.raises(EXC[code]) as info:
        c2blend.Blend.from_file(os.path.join(BAD, name))
    assert fragment in str(info.value)
    assert isinstance(info.value, c2blend.Error)


def test_corpus_is_not_empty():
    assert len(cases()) >= 30
