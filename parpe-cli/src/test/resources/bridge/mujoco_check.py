"""Loads each MJCF model (argument PATH@SECONDS) in MuJoCo 3, holds every servo at its initial
angle for that long in simulated time, and prints one line per model: its name, the warnings
MuJoCo raised, the largest distance (mm) by which a welded loop opened, and whether the state
stayed finite."""
import sys

import mujoco
import numpy as np

for arg in sys.argv[1:]:
    path, seconds = arg.rsplit("@", 1)
    model = mujoco.MjModel.from_xml_path(path)
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    for a in range(model.nu):
        data.ctrl[a] = data.qpos[model.jnt_qposadr[model.actuator_trnid[a, 0]]]
    worst = 0.0
    for _ in range(int(round(float(seconds) / model.opt.timestep))):
        mujoco.mj_step(model, data)
        eq = data.efc_pos[data.efc_type == mujoco.mjtConstraint.mjCNSTR_EQUALITY]
        for k in range(0, len(eq), 6):
            worst = max(worst, float(np.linalg.norm(eq[k:k + 3])))
    warnings = [mujoco.mjtWarning(w).name for w in range(len(data.warning)) if data.warning[w].number > 0]
    finite = bool(np.all(np.isfinite(data.qpos)))
    print("%s warnings=%s loop_mm=%.3f finite=%s" % (path, ",".join(warnings) or "none", worst * 1000, finite))
