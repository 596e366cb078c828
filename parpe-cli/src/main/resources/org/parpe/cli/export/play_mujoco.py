#!/usr/bin/env python3
"""Plays a PARPE gait in MuJoCo (written by `parpe export --target mjcf --robot ROBOT SCRIPT`).

    python3 play_mujoco.py ROBOT.xml ROBOT.ctrl.csv --out trace.csv

ROBOT.ctrl.csv holds one row per tick: the time and, per module m<ID>, the commanded angle in
radians. Each row's angles become the controls of the position actuators m<ID> for one tick
(the model's steps of its own timestep). The trace has PARPE's columns: time, the measured
angle a<ID> of every module in degrees, and the robot's centre of mass com_x, com_y, com_z.
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
    out = sys.stdout if a.out == "-" else open(a.out, "w", newline="")
    out.write(",".join(["time"] + ["a" + n[1:] for n in names] + ["com_x", "com_y", "com_z"]) + "\n")
    mujoco.mj_forward(model, data)
    for row in rows:
        # the state of this tick, then the tick's setpoints drive the next one (as PARPE traces do)
        com = data.subtree_com[root]
        values = [row[0]] + ["%.6f" % math.degrees(data.qpos[j]) for j in joints] + ["%.6f" % c for c in com]
        out.write(",".join(values) + "\n")
        for k, act in enumerate(actuators):
            data.ctrl[act] = float(row[1 + k])
        mujoco.mj_step(model, data, nstep=steps)
    if out is not sys.stdout:
        out.close()


if __name__ == "__main__":
    main()
