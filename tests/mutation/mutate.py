#!/usr/bin/env python3
"""Mutation test of jumoctl's input handling.

Mutates register maps and parameter files and runs jumoctl on each. A finding is a
crash (jumoctl killed by a signal), a hang (the time limit passes), or exit 0 for a file
that a mutation made invalid. Mutations whose result may well be valid (a new label, a
value within range) only have to pass without a crash or a hang.

    mutate.py --jumoctl build/app/jumoctl --count 150 --seed 13     # brief, as CTest runs it
    mutate.py --jumoctl build/app/jumoctl --count 20000 --seed 0    # long, on demand

First the regression inputs in tests/mutation/regressions/ are run (every one must be
refused); the files of new findings are kept (--keep) to be added there.
"""

import argparse
import copy
import json
import os
import random
import shutil
import signal
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.dirname(os.path.dirname(HERE))

# What the map format says about its keys (resources/maps/README.md).
INT_KEYS = {"format", "scanPriority", "maxReadWords", "maxWriteWords", "addressMin", "addressMax",
            "alwaysAnswersAddress", "busErrorTimeoutMs", "words", "bytes", "bit", "width", "exception",
            "decimals", "significantDigits"}
NON_NEGATIVE_KEYS = INT_KEYS | {"processingTimeMaxMs", "turnaroundMs", "minResponseTimeMaxMs"}
HUGE_REFUSED_KEYS = NON_NEGATIVE_KEYS   # every one of them has an upper bound
BOOL_KEYS = {"broadcast", "reserved", "action", "answers"}
ID_KEYS = {"id", "family"}
REQUIRED_ENTRY_KEYS = ["address", "id", "label", "type", "access", "group"]
# Objects whose keys are data, not names from the format.
KEYED_OBJECTS = {"values", "exceptions"}
# Loosely typed by design (numbers or texts), or free text.
FREE_SUBTREES = {"simulation"}
FREE_TEXT_KEYS = {"notes", "erratum", "description", "manual", "name", "label", "unit", "group", "precondition"}


class Finding(Exception):
    pass


class Runner:
    """Runs jumoctl with its own map folder and log folder, with a time limit."""

    def __init__(self, jumoctl, timeout, work):
        self.jumoctl = jumoctl
        self.timeout = timeout
        self.maps = os.path.join(work, "maps")
        self.logs = os.path.join(work, "logs")
        os.makedirs(self.maps)
        os.makedirs(self.logs)
        self.env = dict(os.environ, JUMO_MAP_PATH=self.maps, JUMO_LOG_DIR=self.logs,
                        XDG_DATA_HOME=os.path.join(work, "no-data"), QT_QPA_PLATFORM="offscreen")
        self.runs = 0
        self.longest = 0.0

    def run(self, args):
        self.runs += 1
        started = time.monotonic()
        process = subprocess.Popen([self.jumoctl] + args, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                   stderr=subprocess.PIPE, env=self.env, start_new_session=True)
        try:
            out, err = process.communicate(timeout=self.timeout)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            process.communicate()
            raise Finding("hang: jumoctl %s did not end within %g s" % (" ".join(args), self.timeout))
        self.longest = max(self.longest, time.monotonic() - started)
        if process.returncode < 0:
            raise Finding("crash: jumoctl %s was killed by signal %d" % (" ".join(args), -process.returncode))
        return process.returncode, out.decode(errors="replace"), err.decode(errors="replace")

    def clear_maps(self):
        for name in os.listdir(self.maps):
            path = os.path.join(self.maps, name)
            if os.path.isdir(path) and not os.path.islink(path):
                shutil.rmtree(path)
            else:
                os.remove(path)


# --- Mutations of a JSON tree -------------------------------------------------------

def nodes(tree, path=()):
    """Every (path, value) below tree, the root excluded."""
    if isinstance(tree, dict):
        for key, value in tree.items():
            yield path + (key,), value
            yield from nodes(value, path + (key,))
    elif isinstance(tree, list):
        for index, value in enumerate(tree):
            yield path + (index,), value
            yield from nodes(value, path + (index,))


def get(tree, path):
    for step in path:
        tree = tree[step]
    return tree


def put(tree, path, value):
    get(tree, path[:-1])[path[-1]] = value


def key_of(path):
    """The name of the key a value stands under (list items take their list's name)."""
    for step in reversed(path):
        if isinstance(step, str):
            return step
    return ""


def is_free(path):
    return any(step in FREE_SUBTREES for step in path if isinstance(step, str))


def in_keyed_object(path):
    return len(path) >= 2 and path[-2] in KEYED_OBJECTS


def pick(rng, tree, accept):
    candidates = [(p, v) for p, v in nodes(tree) if not is_free(p) and accept(p, v)]
    return rng.choice(candidates) if candidates else (None, None)


def is_number(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def map_mutations():
    """(name, function(rng, tree) -> (description, must_refuse) or None). Functions change tree."""

    def number_as_string(rng, tree):
        path, value = pick(rng, tree, lambda p, v: is_number(v))
        if path is None:
            return None
        put(tree, path, str(value))
        return "%s: %r -> %r" % ("/".join(map(str, path)), value, str(value)), True

    def fraction(rng, tree):
        path, value = pick(rng, tree, lambda p, v: is_number(v) and key_of(p) in INT_KEYS)
        if path is None:
            return None
        put(tree, path, value + 0.5)
        return "%s: %r -> %r" % ("/".join(map(str, path)), value, value + 0.5), True

    def huge(rng, tree):
        path, value = pick(rng, tree, lambda p, v: is_number(v) and key_of(p) in HUGE_REFUSED_KEYS)
        if path is None:
            return None
        # 100000 is beyond every bound but that of busErrorTimeoutMs (up to an hour).
        new = rng.choice([2147483647, 4294967296, 1e300] + ([100000] if key_of(path) != "busErrorTimeoutMs" else []))
        put(tree, path, new)
        return "%s: %r -> %r" % ("/".join(map(str, path)), value, new), True

    def negative(rng, tree):
        path, value = pick(rng, tree, lambda p, v: is_number(v) and key_of(p) in NON_NEGATIVE_KEYS)
        if path is None:
            return None
        new = rng.choice([-1, -9600, -2147483648])
        put(tree, path, new)
        return "%s: %r -> %r" % ("/".join(map(str, path)), value, new), True

    def bool_as_text(rng, tree):
        path, value = pick(rng, tree, lambda p, v: isinstance(v, bool) and key_of(p) in BOOL_KEYS)
        if path is None:
            return None
        new = rng.choice(["yes", "true", 1, 0])
        put(tree, path, new)
        return "%s: %r -> %r" % ("/".join(map(str, path)), value, new), True

    def text_as_number(rng, tree):
        path, value = pick(rng, tree, lambda p, v: isinstance(v, str) and not in_keyed_object(p)
                           and key_of(p) not in ("models",))
        if path is None:
            return None
        put(tree, path, 16)
        return "%s: %r -> 16" % ("/".join(map(str, path)), value), True

    def unknown_key(rng, tree):
        path, value = pick(rng, tree, lambda p, v: isinstance(v, dict) and p[-1] not in KEYED_OBJECTS)
        target = tree if path is None or rng.random() < 0.1 else value
        target["zz_unknown"] = 1
        return "unknown key in %s" % ("/".join(map(str, path)) if path else "the top level"), True

    def id_with_line_end(rng, tree):
        path, value = pick(rng, tree, lambda p, v: isinstance(v, str) and p[-1] in ID_KEYS)
        if path is None:
            return None
        put(tree, path, value + "\n")
        return "%s: %r + newline" % ("/".join(map(str, path)), value), True

    def remove_required(rng, tree):
        entry = rng.choice(tree["entries"])
        key = rng.choice(REQUIRED_ENTRY_KEYS)
        entry.pop(key, None)
        return "entry %s without %s" % (entry.get("id"), key), True

    def duplicate_entry(rng, tree):
        entry = rng.choice(tree["entries"])
        copies = rng.choice([1, 1, 1, 3000])
        tree["entries"].extend(copy.deepcopy(entry) for _ in range(copies))
        return "entry %s %d more times" % (entry.get("id"), copies), True

    def self_alias(rng, tree):
        entry = rng.choice(tree["entries"])
        entry["alias"] = entry["id"]
        return "entry %s an alias of itself" % entry["id"], True

    def enum_key_zero(rng, tree):
        enums = [e for e in tree["entries"] if isinstance(e.get("values"), dict) and e["values"]]
        if not enums:
            return None
        entry = rng.choice(enums)
        key = rng.choice(list(entry["values"]))
        entry["values"]["0" + key] = "Twice"
        return "enum %s: key 0%s beside %s" % (entry["id"], key, key), True

    def relabel(rng, tree):
        path, value = pick(rng, tree, lambda p, v: isinstance(v, str) and p[-1] in FREE_TEXT_KEYS)
        if path is None:
            return None
        put(tree, path, rng.choice(["", "\u00e4\u00f6\u00fc \u03a9", "x" * 5000, "a\x1b[2Jb", "tab\tnew\nline"]))
        return "%s relabelled" % "/".join(map(str, path)), False

    def shuffle_entries(rng, tree):
        rng.shuffle(tree["entries"])
        return "entries shuffled", False

    return [("number as string", number_as_string), ("fraction", fraction), ("huge number", huge),
            ("negative number", negative), ("boolean as text", bool_as_text), ("text as number", text_as_number),
            ("unknown key", unknown_key), ("id with line end", id_with_line_end),
            ("required key removed", remove_required), ("duplicate entry", duplicate_entry),
            ("alias of itself", self_alias), ("enum key with a zero", enum_key_zero),
            ("text changed", relabel), ("entries shuffled", shuffle_entries)]


def byte_mutation(rng, text):
    """Breaks the JSON text itself: always invalid."""
    data = text.encode()
    choice = rng.randrange(4)
    if choice == 0:
        cut = rng.randrange(1, data.rstrip().rfind(b"}"))
        return data[:cut], "cut at byte %d" % cut
    if choice == 1:
        at = rng.randrange(len(data))
        return data[:at] + b"\x00" + data[at:], "NUL at byte %d" % at
    if choice == 2:
        return b"\xff\xfe" + data, "a UTF-16 byte order mark in front"
    return data.replace(b"{", b"[", 1), "the top level an array"


# --- Map files ------------------------------------------------------------------

def check_map(runner, name, content, must_refuse, description, keep):
    """Puts one mutated file into the map folder and runs jumoctl on it."""
    runner.clear_maps()
    path = os.path.join(runner.maps, name)
    if isinstance(content, str) and content in ("FIFO", "DEVICE", "HUGE"):
        if content == "FIFO":
            os.mkfifo(path)
        elif content == "DEVICE":
            os.symlink("/dev/zero", path)
        else:
            with open(path, "wb") as f:
                f.truncate(64 * 1024 * 1024)
    else:
        with open(path, "wb") as f:
            f.write(content if isinstance(content, bytes) else content.encode())
    try:
        code, out, err = runner.run(["families"])
        if must_refuse and (code == 0 or path not in err):
            raise Finding("accepted: %s (exit %d)" % (description, code))
        family = json.loads(content).get("family") if code == 0 and not isinstance(content, str) else None
        if code == 0 and isinstance(family, str):
            # Accepted: it must serve every command that reads a map.
            for args in (["map", family, "--csv"], ["map", family, "--json"], ["plan", family]):
                runner.run(args)
    except Finding as finding:
        keep_file(keep, name, path, content)
        raise Finding("%s [%s]" % (finding, description))


def keep_file(keep, name, path, content):
    if not keep or content in ("FIFO", "DEVICE", "HUGE"):
        return
    os.makedirs(keep, exist_ok=True)
    target = os.path.join(keep, "%d-%s" % (int(time.time() * 1000) % 10**9, name))
    shutil.copyfile(path, target)


# --- Parameter files --------------------------------------------------------------

def load_maps(folder):
    maps = {}
    for name in sorted(os.listdir(folder)):
        if name.endswith(".json"):
            with open(os.path.join(folder, name)) as f:
                m = json.load(f)
            maps[m["family"]] = m
    return maps


def parameter_mutations(maps):
    def entries(tree):
        return {e["id"]: e for e in maps[tree["family"]]["entries"]}

    def junk_value(rng, tree):
        by_id = entries(tree)
        ids = [i for i in tree["values"] if by_id[i]["type"] != "text"]
        key = rng.choice(ids)
        new = rng.choice(["abc#", "", "0x-1", "0x0x7F", "1,5", "nan", "inf", "1e39", "+", "--1", "12 34"])
        if new == "" and by_id[key]["type"] == "text":
            return None
        tree["values"][key] = new
        return "value of %s -> %r" % (key, new), True

    def value_as_number(rng, tree):
        key = rng.choice(list(tree["values"]))
        tree["values"][key] = 5
        return "value of %s as a JSON number" % key, True

    def unknown_id(rng, tree):
        tree["values"]["zz_unknown"] = "1"
        return "unknown id", True

    def not_a_parameter(rng, tree):
        candidates = [e["id"] for e in maps[tree["family"]]["entries"] if e["access"] == "R"]
        key = rng.choice(candidates)
        tree["values"][key] = "1"
        return "read-only %s as a parameter" % key, True

    def other_family(rng, tree):
        new = rng.choice([f for f in maps if f != tree["family"]] + ["nofamily", "", 7])
        tree["family"] = new
        return "family -> %r" % new, True

    def header(rng, tree):
        key, new = rng.choice([("format", "jumo-parameter"), ("format", 1), ("version", 2), ("version", "1"),
                               ("version", 1.5), ("address", "one"), ("address", 300), ("time", "yesterday"),
                               ("identity", []), ("values", []), ("zz_unknown", 1)])
        tree[key] = new
        return "%s -> %r" % (key, new), True

    def value_in_range(rng, tree):
        by_id = entries(tree)
        floats = [i for i in tree["values"] if by_id[i]["type"] == "float"
                  and "min" not in by_id[i] and "max" not in by_id[i]]
        if not floats:
            return None
        key = rng.choice(floats)
        new = rng.choice(["1.5", "-0", "3.40282347e+38", "1.17549435e-38", "1e-45", "-3.40282347e+38"])
        tree["values"][key] = new
        return "value of %s -> %r" % (key, new), False

    def drop_value(rng, tree):
        key = rng.choice(list(tree["values"]))
        del tree["values"][key]
        return "value of %s removed" % key, False

    return [("junk value", junk_value), ("value as a number", value_as_number), ("unknown id", unknown_id),
            ("not a parameter", not_a_parameter), ("other family", other_family), ("header", header),
            ("value in range", value_in_range), ("value removed", drop_value)]


def check_parameters(runner, seed_path, content, must_refuse, description, work, keep):
    runner.clear_maps()   # the built-in maps only
    path = os.path.join(work, "mutated@line.json")   # an '@' in the name: still a file
    with open(path, "wb") as f:
        f.write(content if isinstance(content, bytes) else content.encode())
    try:
        for args in (["diff", seed_path, path], ["diff", path, seed_path]):
            code, out, err = runner.run(args)
            if must_refuse and code != 2:
                raise Finding("accepted: %s (diff exit %d)" % (description, code))
            if not must_refuse and code not in (0, 1, 2):
                raise Finding("diff exit %d: %s" % (code, description))
    except Finding as finding:
        keep_file(keep, "parameters.json", path, content)
        raise Finding("%s [%s]" % (finding, description))


# --- The run ------------------------------------------------------------------------

def run_regressions(runner, folder, work):
    """Every file in the folder must be refused: map-*.json as a map, parameters-*.json
    compared with its seed (named in the file's "family")."""
    findings = []
    tried = 0
    for name in sorted(os.listdir(folder)) if os.path.isdir(folder) else []:
        path = os.path.join(folder, name)
        with open(path, "rb") as f:
            content = f.read()
        tried += 1
        try:
            if name.startswith("map-"):
                check_map(runner, name, content, True, "regression " + name, None)
            elif name.startswith("parameters-"):
                family = name.split("-")[1]
                seed = os.path.join(HERE, "seeds", "%s-parameters.json" % family)
                check_parameters(runner, seed, content, True, "regression " + name, work, None)
        except Finding as finding:
            findings.append(str(finding))
    return tried, findings


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--jumoctl", required=True)
    parser.add_argument("--maps", default=os.path.join(SOURCE, "resources", "maps"))
    parser.add_argument("--count", type=int, default=150, help="random mutations (default 150)")
    parser.add_argument("--seed", type=int, default=13, help="random seed; 0 picks one")
    parser.add_argument("--timeout", type=float, default=20, help="seconds per jumoctl run (default 20)")
    parser.add_argument("--keep", help="folder for the files of findings")
    args = parser.parse_args()
    seed = args.seed or random.SystemRandom().randrange(1, 2**31)
    rng = random.Random(seed)
    maps = load_maps(args.maps)
    map_texts = {f: json.dumps(m, indent=1, ensure_ascii=False) for f, m in maps.items()}
    seeds = {}
    for family in maps:
        path = os.path.join(HERE, "seeds", "%s-parameters.json" % family)
        if os.path.exists(path):
            with open(path) as f:
                seeds[family] = (path, json.load(f))

    started = time.monotonic()
    work = tempfile.mkdtemp(prefix="jumo-mutate-")
    findings = []
    kinds = {}
    try:
        runner = Runner(args.jumoctl, args.timeout, work)
        tried, regression_findings = run_regressions(runner, os.path.join(HERE, "regressions"), work)
        findings += regression_findings
        map_ops = map_mutations()
        parameter_ops = parameter_mutations(maps)
        for n in range(args.count):
            what = rng.random()
            try:
                if what < 0.55:
                    family = rng.choice(sorted(maps))
                    tree = json.loads(map_texts[family])
                    name, op = rng.choice(map_ops)
                    result = op(rng, tree)
                    if result is None:
                        continue
                    description, must_refuse = result
                    check_map(runner, family + ".json", json.dumps(tree, ensure_ascii=False), must_refuse,
                              "%s map: %s" % (family, description), args.keep)
                elif what < 0.62:
                    family = rng.choice(sorted(maps))
                    special = rng.choice(["FIFO", "DEVICE", "HUGE", None])
                    if special:
                        name = "special file: " + special
                        check_map(runner, family + ".json", special, True, name, args.keep)
                    else:
                        data, description = byte_mutation(rng, map_texts[family])
                        name = "bytes"
                        check_map(runner, family + ".json", data, True, "%s map: %s" % (family, description),
                                  args.keep)
                else:
                    family = rng.choice(sorted(seeds))
                    seed_path, seed_tree = seeds[family]
                    if rng.random() < 0.1:
                        data, description = byte_mutation(rng, json.dumps(seed_tree, indent=1))
                        name = "parameter bytes"
                        check_parameters(runner, seed_path, data, True, "%s parameters: %s" % (family, description),
                                         work, args.keep)
                    else:
                        tree = copy.deepcopy(seed_tree)
                        name, op = rng.choice(parameter_ops)
                        result = op(rng, tree)
                        if result is None:
                            continue
                        description, must_refuse = result
                        check_parameters(runner, seed_path, json.dumps(tree), must_refuse,
                                         "%s parameters: %s" % (family, description), work, args.keep)
                kinds[name] = kinds.get(name, 0) + 1
                tried += 1
            except Finding as finding:
                findings.append(str(finding))
                tried += 1
    finally:
        shutil.rmtree(work, ignore_errors=True)

    elapsed = time.monotonic() - started
    print("seed %d: %d files tried (%s), %d jumoctl runs, longest %.2f s, %.0f s in all; %d finding(s)"
          % (seed, tried, ", ".join("%s %d" % kv for kv in sorted(kinds.items())), runner.runs, runner.longest,
             elapsed, len(findings)))
    for finding in findings:
        print("FINDING: " + finding)
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
