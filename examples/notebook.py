# %% [markdown]
# # zipopt from Python
# Notebook-style cells (`# %%`: Jupyter, VS Code and Spyder run them one by one). Simulate the
# seed scene at a gentle push, look at the chain, then search for the fastest survivable drive.
# Installed (cmake --install), run it from anywhere: python3 PREFIX/share/zipopt/examples/notebook.py
# (PYTHONPATH=PREFIX/lib/python3.X/dist-packages for a prefix python3 does not search). From the
# source tree: PYTHONPATH=python ZIPOPT_LIB=build/src/lib/libzipopt.so python3 examples/notebook.py

# %%
import math
import os

import zipopt

SCENE = os.environ.get("ZIPOPT_SCENE") or zipopt.example_scene("seed.ini")
print("zipopt", zipopt.library_version())

# %% one run: outcome, time, energy audit
r = zipopt.simulate(SCENE, forces=[10, 10, 10])
print(r)
print(f"outcome {r.outcome}, finish {r.time:.6f} s, kinks crossed {r.kinks}")
print(f"energy audit residual {r.energy_residual:.2e} J (of {r.e_initial:.0f} J)")
print("largest relative joint angles (deg):", [round(math.degrees(a), 2) for a in r.max_angles])
print(r.crossings)

# %% the trajectory is a dict of numpy columns
tr = r.trajectory
print(sorted(tr))
print(f"{len(tr['t'])} rows; top speed {tr['speed'].max():.2f} m/s")

# %% the fastest survivable schedule (a small budget here; the scene's [optimize] by default)
def progress(evals, wall_s, found, time, forces, improved):
    if improved and found:
        print(f"  {evals:5d} simulations, {wall_s:5.2f} s: {time:.4f} s with {forces.round(2)}")
    return False  # True would stop the search


best = zipopt.search(SCENE, max_evals=int(os.environ.get("ZIPOPT_EVALS", "600")),
                     progress=progress)
print(best)
fast = zipopt.simulate(SCENE, forces=best.forces)
print(f"the best schedule rerun: {fast.outcome} at {fast.time:.6f} s")

# %% figures, when matplotlib is installed (apt-get install python3-matplotlib)
try:
    import matplotlib

    matplotlib.use(os.environ.get("MPLBACKEND", "Agg"))
    import matplotlib.pyplot as plt
except ImportError:
    plt = None
    print("matplotlib is not installed: no figures")

if plt:
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
    for run, label in ((r, "10 N each"), (fast, "searched")):
        ax1.plot(run.trajectory["t"], run.trajectory["speed"], label=f"trolley, {label}")
        for i in range(1, len(run.max_angles) + 1):
            ax2.plot(run.trajectory["t"], [math.degrees(p) for p in run.trajectory[f"phi{i}"]],
                     label=f"phi{i}, {label}")
    ax1.set_xlabel("t (s)")
    ax1.set_ylabel("speed (m/s)")
    ax1.legend()
    ax2.set_xlabel("t (s)")
    ax2.set_ylabel("relative joint angle (deg)")
    ax2.legend(fontsize="small", ncol=2)
    fig.tight_layout()
    out = os.environ.get("ZIPOPT_FIGURE", "notebook.png")
    fig.savefig(out)
    print("wrote", out)
