"""The program sandbox: hostile programs are rejected or stopped, naming the line; good ones run."""

from __future__ import annotations

import re
import time
from dataclasses import dataclass

import pytest

from realsim.errors import InputError
from realsim.planner.sandbox import Limits, SandboxViolation, check, run


@dataclass
class Result:
    success: bool = True
    reason: str = ""


class Recorder:
    """Primitive functions that only record their calls (a unit test of the sandbox, not the robot)."""

    def __init__(self, fail: set[str] | None = None):
        self.calls: list[tuple] = []
        self.fail = fail or set()
        self.poses = {"obj1_mug": (0.5, 0.1, 0.05), "obj2_bowl": (0.5, -0.2, 0.03), "obj3_block": (0.6, 0.2, 0.02)}

    def _act(self, name: str, *args: object) -> Result:
        self.calls.append((name, *args))
        return Result(name not in self.fail, f"{name} failed on purpose" if name in self.fail else "")

    def go_home(self): return self._act("go_home")
    def move_ee_to(self, pos, quat=None): return self._act("move_ee_to", list(pos), quat)
    def open_gripper(self): return self._act("open_gripper")
    def close_gripper(self): return self._act("close_gripper")
    def grasp(self, obj): return self._act("grasp", obj)
    def place(self, obj, pos): return self._act("place", obj, [round(float(v), 4) for v in pos])
    def place_on(self, obj, target): return self._act("place_on", obj, target)
    def place_in(self, obj, container): return self._act("place_in", obj, container)
    def place_beside(self, obj, ref, side="next"): return self._act("place_beside", obj, ref, side)
    def place_between(self, obj, a, b): return self._act("place_between", obj, a, b)
    def place_down(self, obj): return self._act("place_down", obj)
    def push(self, obj, direction, distance): return self._act("push", obj, direction, distance)
    def open_drawer(self, obj): return self._act("open_drawer", obj)
    def close_drawer(self, obj): return self._act("close_drawer", obj)

    def object_pose(self, name):
        if name not in self.poses:
            raise KeyError(f"no object {name!r}")
        self.calls.append(("object_pose", name))
        return list(self.poses[name]), (1.0, 0.0, 0.0, 0.0)

    def object_names(self):
        self.calls.append(("object_names",))
        return list(self.poses)


FAST = Limits(max_seconds=1.0, max_steps=50_000)

# (program, line the message must name); every one must be rejected before running or stopped.
HOSTILE: list[tuple[str, int]] = [
    ("import os", 1),
    ("from os import system", 1),
    ("grasp('obj1_mug')\nimport subprocess", 2),
    ("__import__('os').system('ls')", 1),
    ("().__class__.__bases__[0].__subclasses__()", 1),
    ("x = ()\ny = x.__class__", 2),
    ("object_names.__globals__", 1),
    ("grasp.__code__", 1),
    ("print.__self__.open('/etc/passwd')", 1),
    ("getattr(grasp, '__globals__')", 1),
    ("setattr(grasp, 'x', 1)", 1),
    ("eval('1+1')", 1),
    ("exec('import os')", 1),
    ("compile('1', 'f', 'eval')", 1),
    ("open('/etc/passwd').read()", 1),
    ("f = open\nf('/tmp/x', 'w')", 1),
    ("globals()['grasp']", 1),
    ("locals()", 1),
    ("vars()", 1),
    ("type(1)", 1),
    ("super()", 1),
    ("x = '{0.__class__}'.format(1)", 1),
    ("s = 'a'\nt = s.format(1)", 2),
    ("x = 'abc'.upper()", 1),
    ("x = f'{1:>100000000}'", 1),
    ("x = '%s' % 1", 1),
    ("f = lambda: 1", 1),
    ("x = (lambda: grasp)()", 1),
    ("def f():\n    pass", 1),
    ("@decorator\ndef f():\n    pass", 1),
    ("class A:\n    pass", 1),
    ("with open('x') as f:\n    pass", 1),
    ("try:\n    grasp('obj1_mug')\nexcept Exception:\n    pass", 1),
    ("global x", 1),
    ("if (n := 10):\n    grasp('obj1_mug')", 1),
    ("y = [x := 1 for i in range(3)]", 1),
    ("del grasp", 1),
    ("x = 10**10**10", 1),
    ("x = [0]*10**10", 1),
    ("x = 2**1000", 1),
    ("x = 'a' * 100000000", 1),
    ("x = range(10**9)", 1),
    ("for i in range(100000000):\n    pass", 1),
    ("x = 1 << 100000", 1),
    ("x = ~1", 1),
    ("x = {'a': 1}", 1),
    ("x = (i for i in range(3))", 1),
    ("grasp(*['obj1_mug'])", 1),
    ("grasp(**{'obj': 'x'})", 1),
    ("_ = 1\n__builtins__", 2),
    ("x = _private", 1),
    ("x = b'bytes'", 1),
    ("import socket\nsocket.create_connection(('example.com', 80))", 1),
    ("x = grasp\nx.__call__('obj1_mug')", 2),
    ("grasp('obj1_mug').__class__.__init__.__globals__", 1),
    ("x = 1\nx.y = 2", 2),
    ("async def f():\n    await g()", 1),
    ("match x:\n    case 1:\n        pass", 1),
    ("breakpoint()", 1),
    ("x = 'a' * 20000", 1),
    ("", 1),
    ("grasp('obj1_mug'", 1),
    ("range = 5", 1),
    ("x = 1\n" + "x = x + 1\n" * 3000, 1),
]

# programs that pass the static check but must be stopped at run time, with the line named
RUNAWAY: list[tuple[str, int, str]] = [
    ("while True:\n    pass", 1, "while loop ran more than"),
    ("n = 0\nwhile n >= 0:\n    n = n + 1", 2, "while loop ran more than"),
    ("for i in range(9000):\n    for j in range(9000):\n        pass", 3, "steps|longer than"),  # a loaded machine may hit the time budget first
    ("x = [0]\nfor i in range(100):\n    x = x + x", 3, "elements"),
    ("x = [0] * 9999\ny = x * 9999", 2, "repetition"),
    ("n = 10\nfor i in range(40):\n    n = n * n", 3, "too large"),
    ("n = 99\nm = n ** 60", 2, "too large"),
    ("x = [0] * 5000\nys = [x[:] for i in range(5000)]", 2, "in total"),
    ("x = []\nfor i in range(10000):\n    x.append(i)\nx.append(1)\nx.append(2)", 5, "elements"),
    ("n = 100000\nr = range(n * n)", 2, "too long"),
    ("for i in range(100):\n    grasp('obj1_mug')", 2, "primitive calls"),
    ("s = 'ab'\nfor i in range(30):\n    s = s + s", 3, "elements"),
    ("x = 1 / 0", 1, "ZeroDivisionError"),
    ("p, q = object_pose('nothing')", 1, "raised KeyError"),
    ("x = [1, 2]\ny = x[5]", 2, "IndexError"),
    ("x = sum([[1], [2]])", 1, "only adds numbers"),
]


@pytest.mark.parametrize(("program", "line"), HOSTILE, ids=[f"hostile{i:02d}" for i in range(len(HOSTILE))])
def test_hostile_program_is_rejected_naming_the_line(program: str, line: int) -> None:
    rec = Recorder()
    with pytest.raises(SandboxViolation) as info:
        run(program, rec, limits=FAST)
    message = str(info.value)
    assert f"line {line}:" in message, message
    assert "\n" not in message
    assert rec.calls == []
    assert isinstance(info.value, InputError) and info.value.exit_code == 2


@pytest.mark.parametrize(("program", "line", "why"), RUNAWAY, ids=[f"runaway{i:02d}" for i in range(len(RUNAWAY))])
def test_runaway_program_is_stopped_naming_the_line(program: str, line: int, why: str) -> None:
    t0 = time.thread_time()  # CPU: the budgets count the program's CPU time, so a loaded machine cannot fail this
    report = run(program, Recorder(), limits=FAST)
    assert time.thread_time() - t0 < 5.0
    assert report.error is not None and not report.ok
    assert report.error.startswith(f"line {line}:"), report.error
    assert re.search(why, report.error), report.error


def test_cpu_time_budget_stops_a_busy_program() -> None:
    program = "t = 0\nfor i in range(10000):\n    for j in range(10000):\n        t = t + i * j"
    t0 = time.thread_time()
    report = run(program, Recorder(), limits=Limits(max_steps=10**9, max_seconds=0.3))
    assert report.error is not None and "longer than 0.3 s" in report.error
    assert re.match(r"line [234]:", report.error)
    assert time.thread_time() - t0 < 3.0


def test_corpus_sizes() -> None:
    assert len(HOSTILE) + len(RUNAWAY) >= 40


def test_rejection_lists_every_problem() -> None:
    with pytest.raises(SandboxViolation) as info:
        check("import os\nx = eval('1')\ny = grasp.__code__")
    assert [v.split(":")[0] for v in info.value.violations] == ["line 1", "line 2", "line 3"]


def test_good_program_calls_primitives_in_order() -> None:
    program = """
# put every object but the bowl in the bowl, then push the block and go home
for name in object_names():
    if name != "obj2_bowl":
        r = place_in(name, "obj2_bowl")
        print(name, r.success)
p, _ = object_pose("obj3_block")
place("obj1_mug", [p[0], p[1] + 0.1, p[2]])
push("obj3_block", "left", 0.05)
n = 0
while n < 2:
    n += 1
open_drawer("obj1_mug")
go_home()
"""
    rec = Recorder()
    report = run(program, rec)
    assert report.ok, report.error
    names = [c[0] for c in rec.calls]
    assert names == ["object_names", "place_in", "place_in", "object_pose", "place", "push", "open_drawer", "go_home"]
    assert rec.calls[4] == ("place", "obj1_mug", [0.6, 0.3, 0.02])
    assert [c.name for c in report.calls] == names
    assert report.calls[1].line == 5 and report.calls[1].args == ("obj1_mug", "obj2_bowl")
    assert report.output == ["obj1_mug True", "obj3_block True"]
    assert "line 9: push('obj3_block', 'left', 0.05) -> ok" in report.summary()


def test_builtins_and_expressions_work() -> None:
    program = """
names = sorted(object_names())
k = len(names)
xs = [object_pose(n)[0][0] for n in names]
far = max(xs)
total = sum(xs) / k
idx = [i for i, n in enumerate(names) if n.success if False] if False else list(range(k))
pairs = list(zip(names, xs))
s = f"{k} objects, farthest x {round(far, 2)}, mean {round(total, 3)!r}"
print(s, abs(-2), min(1, 2), int(2.7), float(1), str(3), bool(0), 2 ** 0.5 > 1, -k ** 2)
move_ee_to([0.4, 0.0, 0.3 + 0.1 * (k > 2)], quat=None)
"""
    report = run(program, Recorder())
    assert report.ok, report.error
    assert report.output == ["3 objects, farthest x 0.6, mean 0.533 2 1 2 1.0 3 False True -9"]


def test_failed_primitive_stops_the_program() -> None:
    rec = Recorder(fail={"grasp"})
    report = run("open_gripper()\ngrasp('obj1_mug')\ngo_home()", rec)
    assert report.error == "line 2: grasp('obj1_mug') failed: grasp failed on purpose"
    assert [c[0] for c in rec.calls] == ["open_gripper", "grasp"]
    assert not report.calls[-1].success


def test_failed_primitive_can_be_handled_when_allowed() -> None:
    rec = Recorder(fail={"grasp"})
    program = "r = grasp('obj1_mug')\nif not r.success:\n    print('retry:', r.reason)\n    go_home()"
    report = run(program, rec, limits=Limits(stop_on_failure=False))
    assert report.ok and report.output == ["retry: grasp failed on purpose"]
    assert [c[0] for c in rec.calls] == ["grasp", "go_home"]


def test_missing_primitive_is_named() -> None:
    with pytest.raises(SandboxViolation, match=r"line 2: primitive close_drawer\(\) is not provided"):
        run("go_home()\nclose_drawer('d')", {"go_home": lambda: Result()})


def test_tracing_is_restored_after_run() -> None:
    import sys

    before = sys.gettrace()
    run("while True:\n    pass", Recorder(), limits=FAST)
    run("go_home()", Recorder())
    assert sys.gettrace() is before
