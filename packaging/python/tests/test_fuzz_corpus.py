"""The kept fuzz corpus: the greedy choice by coverage features from a merge control file."""

from fsc import fuzz_corpus


def write_inputs(tmp_path, sizes):
    paths = []
    for name, size in sizes.items():
        path = tmp_path / name
        path.write_bytes(b"x" * size)
        paths.append(str(path))
    return paths


def test_the_control_file_gives_each_executed_input_its_features(tmp_path):
    a, b, c = write_inputs(tmp_path, {"a": 1, "b": 2, "c": 3})
    control = tmp_path / "control"
    control.write_text(
        f"3\n0\n{a}\n{b}\n{c}\nSTARTED 0 1\nFT 0 1 2 3\nCOV 0 7\nSTARTED 2 3\nFT 2 4\nCOV 2 8\n"
    )
    assert fuzz_corpus.read_control_file(str(control)) == {a: {1, 2, 3}, c: {4}}


def test_the_choice_takes_the_largest_gain_first_and_stops_at_the_limit_or_no_gain(tmp_path):
    a, b, c, d = write_inputs(tmp_path, {"a": 5, "b": 1, "c": 9, "d": 1})
    features = {a: {1, 2}, b: {1, 2}, c: {1, 2, 3, 4}, d: {5}}
    # c covers the most; then d adds 5; a and b add nothing.
    assert fuzz_corpus.select(features, 10) == [c, d]
    assert fuzz_corpus.select(features, 1) == [c]
    # On equal gain the smaller input wins.
    assert fuzz_corpus.select({a: {1, 2}, b: {1, 2}}, 10) == [b]


def test_the_destination_holds_exactly_the_chosen_inputs(tmp_path, capsys):
    a, b, c = write_inputs(tmp_path, {"a": 1, "b": 1, "c": 1})
    control = tmp_path / "control"
    control.write_text(f"3\n0\n{a}\n{b}\n{c}\nFT 0 1\nFT 1 1 2\nFT 2 3\n")
    destination = tmp_path / "corpus"
    destination.mkdir()
    (destination / "old").write_bytes(b"old")
    assert fuzz_corpus.main([str(control), str(destination), "--limit", "1"]) == 0
    assert sorted(p.name for p in destination.iterdir()) == ["b"]
    assert "1 of 3 inputs kept, 2 of 3 features (66.7%)" in capsys.readouterr().out
