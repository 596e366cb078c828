#!/usr/bin/env python3
"""Plays a PARPE gait in MuJoCo (written by `parpe export --target mjcf --robot ROBOT SCRIPT`).

    python3 play_mujoco.py ROBOT.xml ROBOT.ctrl.csv --out trace.csv

ROBOT.ctrl.csv holds one row per tick: the time and, per module m<ID>, the commanded angle in
radians. Each row's angles drive the position actuators m<ID> for one tick (the model's steps of
its own timestep), through the servo's speed limit as PARPE's servo has it: at every step the
control is at most speed/gain ahead of the measured angle (the model's custom numeric
"servo_speed", rad/s, and its actuators' kp/kv), so the servo turns at most that fast. The trace has PARPE's columns: time, the measured
angle a<ID> of every module in degrees, and the robot's centre of mass com_x, com_y, com_z.
With --metrics, also what `parpe run --metrics` writes: how far the centre of mass moved (distance,
dx, dy, speed) and the largest tilt in degrees (of the root's initially upward axis, or for a
rolling robot twice the change of its axle's slope, the model's site "axle"); over 90 is a fall.
A gait of a script with latches (PARSL 1.1 section 14) also has a column plate<ID>_<P> per
latchable plate, the tick's plate action (0 none, 1 arm, 2 release); the model has, per pair of
such plates, four inactive welds latch_<A>__<B>_r<0|90|180|270> (one per 90-degree step of the
aligned pose). An armed plate latches onto a free plate of its pairs when their sites' centres
are within PARPE's draw distance and the pair's pose is within its draw angle of a weld's aligned
pose (the model's custom numeric "latch_catch": distance m, angle rad): that weld is switched on
(data.eq_active) and pulls the plates home as PARPE's draw and pins do; a release of either
plate switches it off. --latches FILE
writes each latch and release: time, event, weld.
Needs the `mujoco` Python package (MuJoCo 3).
"""
import argparse
import csv
import math
import sys

import mujoco
import numpy


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("model")
    p.add_argument("controls")
    p.add_argument("--out", default="-", help="trace CSV (default: standard output)")
    p.add_argument("--metrics", help="write distance, speed and tilt as JSON to this file ('-': standard output)")
    p.add_argument("--latches", help="write the latch events as CSV to this file")
    a = p.parse_args()
    model = mujoco.MjModel.from_xml_path(a.model)
    data = mujoco.MjData(model)
    with open(a.controls, newline="") as f:
        rows = list(csv.reader(f))
    header, rows = rows[0], rows[1:]
    plates = [k for k, n in enumerate(header) if n.startswith("plate")]
    names = [n for k, n in enumerate(header[1:], 1) if k not in plates]
    actuators = [model.actuator(n).id for n in names]
    joints = [model.joint(n).qposadr[0] for n in names]
    root = model.body("world").id
    tick = float(rows[1][0]) - float(rows[0][0]) if len(rows) > 1 else model.opt.timestep
    steps = max(1, round(tick / model.opt.timestep))
    lead = [speed_lead(model, act) for act in actuators]
    latch = Latches(model, data, [header[k] for k in plates])
    out = sys.stdout if a.out == "-" else open(a.out, "w", newline="")
    out.write(",".join(["time"] + ["a" + n[1:] for n in names] + ["com_x", "com_y", "com_z"]) + "\n")
    mujoco.mj_forward(model, data)
    tilt = Tilt(model, data)
    start = data.subtree_com[root].copy()
    for i, row in enumerate(rows):
        # the state of this tick, then the tick's setpoints drive the next one (as PARPE traces do);
        # the last row is the state at the end of the run
        com = data.subtree_com[root]
        values = [row[0]] + ["%.6f" % math.degrees(data.qpos[j]) for j in joints] + ["%.6f" % c for c in com]
        out.write(",".join(values) + "\n")
        if i == len(rows) - 1:
            break
        targets = [float(x) for k, x in enumerate(row[1:], 1) if k not in plates]
        latch.act(float(row[0]), [int(row[k]) for k in plates])
        for _ in range(steps):
            for k, act in enumerate(actuators):
                q = data.qpos[joints[k]]
                data.ctrl[act] = q + max(-lead[k], min(lead[k], targets[k] - q))
            mujoco.mj_step(model, data)
        tilt.update()
        latch.catch(float(rows[i + 1][0]))
    if out is not sys.stdout:
        out.close()
    if a.latches:
        with open(a.latches, "w") as f:
            f.write("time,event,weld\n" + "".join("%.6f,%s,%s\n" % e for e in latch.events))
    if a.metrics:
        duration = (len(rows) - 1) * tick
        dx, dy = (data.subtree_com[root][k] - start[k] for k in (0, 1))
        text = ('{"duration": %.6f, "distance": %.6f, "dx": %.6f, "dy": %.6f, "speed": %.6f, "maxTiltDeg": %.6f}\n'
                % (duration, math.hypot(dx, dy), dx, dy, math.hypot(dx, dy) / duration if duration > 0 else 0.0, math.degrees(tilt.worst)))
        if a.metrics == "-":
            sys.stdout.write(text)
        else:
            with open(a.metrics, "w") as f:
                f.write(text)


def speed_lead(model, act):
    """How far, rad, the control may lead the angle: the servo's speed over its gain kp/kv."""
    speed = [i for i in range(model.nnumeric) if model.numeric(i).name == "servo_speed"]
    kp, kv = -model.actuator_biasprm[act][1], -model.actuator_biasprm[act][2]
    if not speed or kp <= 0 or kv <= 0:
        return math.inf
    return float(model.numeric_data[model.numeric_adr[speed[0]]]) * kv / kp


class Latches:
    """The welds of latchable plate pairs, switched on and off as PARPE's latches close and open."""

    def __init__(self, model, data, plates):
        self.model, self.data = model, data
        self.plates = plates
        self.armed = {p: False for p in plates}
        self.on = {}  # plate -> the active weld's id
        self.events = []
        lock = [i for i in range(model.nnumeric) if model.numeric(i).name == "latch_catch"]
        adr = model.numeric_adr[lock[0]] if lock else 0
        self.distance, self.angle = (model.numeric_data[adr], model.numeric_data[adr + 1]) if lock else (0.0, 0.0)
        self.welds = []  # (plate a, plate b, [weld ids])
        for i in range(model.neq):
            name = model.equality(i).name
            if name.startswith("latch_"):
                a, b = name[len("latch_"):].rsplit("_r", 1)[0].split("__")
                if not self.welds or self.welds[-1][:2] != (a, b):
                    self.welds.append((a, b, []))
                self.welds[-1][2].append(i)

    def act(self, time, actions):
        """Applies a tick's plate actions: arm, or release (and part a latched pair)."""
        for plate, act in zip(self.plates, actions):
            if act == 1:
                self.armed[plate] = True
            elif act == 2:
                self.armed[plate] = False
                if plate in self.on:
                    weld = self.on[plate]
                    self.data.eq_active[weld] = 0
                    self.events.append((time, "release", self.model.equality(weld).name))
                    for a, b, ids in self.welds:
                        if weld in ids:
                            del self.on[a], self.on[b]

    def catch(self, time):
        """Latches every pair with an armed plate, both plates free, within the lock distance and angle."""
        for a, b, ids in self.welds:
            if not (self.armed.get(a) or self.armed.get(b)) or a in self.on or b in self.on:
                continue
            sa, sb = self.model.site(a).id, self.model.site(b).id
            gap = self.data.site_xpos[sa] - self.data.site_xpos[sb]
            if math.sqrt(sum(g * g for g in gap)) > self.distance:
                continue
            best = min(ids, key=self.misalignment)
            if self.misalignment(best) <= self.angle:
                self.data.eq_active[best] = 1
                self.on[a] = self.on[b] = best
                self.events.append((time, "latch", self.model.equality(best).name))

    def misalignment(self, weld):
        """The angle, rad, between body2's orientation and the one weld's aligned pose gives it."""
        m, d = self.model, self.data
        b1, b2 = m.eq_obj1id[weld], m.eq_obj2id[weld]
        want = numpy.zeros(4)
        mujoco.mju_mulQuat(want, d.xquat[b1], numpy.array(m.eq_data[weld][6:10]))
        dot = abs(sum(want[k] * d.xquat[b2][k] for k in range(4)))
        return 2 * math.acos(min(1.0, dot))


class Tilt:
    """The largest tilt so far, as PARPE measures it (docs/simulator.md, --metrics)."""

    def __init__(self, model, data):
        self.data = data
        self.worst = 0.0
        axle = [i for i in range(model.nsite) if model.site(i).name == "axle"]
        self.axle = axle[0] if axle else None
        # the root body: the one with the free joint
        self.root = int(model.jnt_bodyid[[j for j in range(model.njnt) if model.jnt_type[j] == 0][0]])
        if self.axle is not None:
            self.slope0 = self.slope()
        else:
            self.up = [data.xmat[self.root][6 + k] for k in range(3)]

    def slope(self):
        z = self.data.site_xmat[self.axle][8]
        return math.asin(max(-1.0, min(1.0, z)))

    def update(self):
        if self.axle is not None:
            t = min(math.pi, 2 * abs(self.slope() - self.slope0))
        else:
            z = sum(self.data.xmat[self.root][6 + k] * self.up[k] for k in range(3))
            t = math.acos(max(-1.0, min(1.0, z)))
        self.worst = max(self.worst, t)


if __name__ == "__main__":
    main()
