"""The package's namespace is its API: what ``dir(repro)`` lists without a leading underscore
is ``repro.__all__``, and no helper module or typing name leaks into it."""

import repro


def test_dir_lists_the_api_only():
    public = {name for name in dir(repro) if not name.startswith("_")}
    assert public == set(repro.__all__)
    for leaked in ("Any", "Callable", "Dict", "Mapping", "np", "os", "csv", "tempfile", "annotations"):
        assert leaked not in dir(repro), leaked


def test_star_import_gives_the_api():
    namespace = {}
    exec("from repro import *", namespace)
    assert {k for k in namespace if k != "__builtins__"} == set(repro.__all__)
