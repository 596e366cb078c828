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
Needs the `mujoco` Python package (MuJoCo 3).
"""
import argparse
import csv
import math
import sys

import mujoco


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("model")
    p.add_argument("controls")
    p.add_argument("--out", default="-", help="trace CSV (default: standard output)")
    p.add_argument("--metrics", help="write distance, speed and tilt as JSON to this file ('-': standard output)")
    a = p.parse_args()
    model = mujoco.MjModel.from_xml_path(a.model)
    data = mujoco.MjData(model)
    with open(a.controls, newline="") as f:
        rows = list(csv.reader(f))
    header, rows = rows[0], rows[1:]
    names = header[1:]
    actuators = [model.actuator(n).id for n in names]
    joints = [model.joint(n).qposadr[0] for n in names]
    root = model.body("world").id
    tick = float(rows[1][0]) - float(rows[0][0]) if len(rows) > 1 else model.opt.timestep
    steps = max(1, round(tick / model.opt.timestep))
    lead = [speed_lead(model, act) for act in actuators]
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
        targets = [float(x) for x in row[1:]]
        for _ in range(steps):
            for k, act in enumerate(actuators):
                q = data.qpos[joints[k]]
                data.ctrl[act] = q + max(-lead[k], min(lead[k], targets[k] - q))
            mujoco.mj_step(model, data)
        tilt.update()
    if out is not sys.stdout:
        out.close()
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
