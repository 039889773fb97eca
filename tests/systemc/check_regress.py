#!/usr/bin/python3
"""Checks of `scurve regress` output, run by ctest.

  check_regress.py junit DIR [NAME...]  junit.xml is valid XML with one passing
                                        testcase per results.json entry, among
                                        them the named ones
  check_regress.py shards SCURVE LIST TMP
                                        runs LIST unsharded, as 1/2 and 2/2 and
                                        merged: the same tests, all passing
"""
import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ET


def check_junit(out_dir, required):
    root = ET.parse(os.path.join(out_dir, "junit.xml")).getroot()
    assert root.tag == "testsuites", root.tag
    suites = root.findall("testsuite")
    assert len(suites) == 1
    cases = suites[0].findall("testcase")
    results = json.load(open(os.path.join(out_dir, "results.json")))
    assert len(cases) == results["tests"] == int(suites[0].get("tests")), (len(cases), results["tests"])
    assert int(suites[0].get("failures")) == 0, "failures in junit.xml"
    for c in cases:
        assert c.get("name") and c.get("classname") and float(c.get("time")) >= 0
        assert c.find("failure") is None, c.get("name")
    names = {c.get("name") for c in cases}
    assert set(required) <= names, (sorted(set(required) - names), names)
    print(f"junit.xml: {len(cases)} testcases, all passed")


def run(cmd):
    print(" ".join(cmd), flush=True)
    return subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


def names_of(path):
    return sorted(r["name"] for r in json.load(open(path))["results"])


def check_shards(scurve, test_list, tmp):
    base = [scurve, "regress", "--list", test_list, "--jobs", "2"]
    outs = {}
    for tag, extra in (("all", []), ("s1", ["--shard", "1/2"]), ("s2", ["--shard", "2/2"])):
        out = os.path.join(tmp, tag)
        r = run(base + ["--out-dir", out] + extra)
        assert r.returncode == 0, r.stdout
        outs[tag] = os.path.join(out, "results.json")
    s1, s2 = names_of(outs["s1"]), names_of(outs["s2"])
    assert not set(s1) & set(s2), "shards overlap"
    assert sorted(s1 + s2) == names_of(outs["all"]), (s1, s2, names_of(outs["all"]))
    merged = os.path.join(tmp, "merged")
    r = run([scurve, "regress", "--merge", outs["s1"], outs["s2"], "--out-dir", merged])
    assert r.returncode == 0, r.stdout
    assert names_of(os.path.join(merged, "results.json")) == names_of(outs["all"])
    ET.parse(os.path.join(merged, "junit.xml"))
    print(f"shards 1/2 {s1} + 2/2 {s2} == unsharded; merge ok")


if __name__ == "__main__":
    if sys.argv[1] == "junit":
        check_junit(sys.argv[2], sys.argv[3:])
    elif sys.argv[1] == "shards":
        check_shards(*sys.argv[2:5])
    else:
        sys.exit(__doc__)
