"""Figures of a rig run (matplotlib, imported on use): the content of the seed
paper's Fig. 7 (creepage and speeds against time) and Fig. 8 (adhesion
force against time)."""
import os

__all__ = ["plot_run"]


def plot_run(res, outdir, prefix="rig"):
    """Write <prefix>_creepage.png (Fig. 7) and <prefix>_force.png (Fig. 8)
    for RigResult `res` into outdir; returns the paths."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    os.makedirs(outdir, exist_ok=True)
    t = res.time
    paths = []

    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(8, 6.4), sharex=True)
    ax1.plot(t, res.creepage, lw=0.8, label="creepage (contact model)")
    ax1.plot(t, res.xi_est, lw=0.6, alpha=0.7, label="estimate from the encoders (eq. 16)")
    ax1.step(t, res.xi_ref, where="post", color="k", lw=1.0, ls="--", label="target")
    ax1.set_ylabel("longitudinal creepage [-]")
    ax1.legend(fontsize=8, loc="upper right")
    ax1.grid(alpha=0.3)
    ax2.plot(t, res.roller_speed, label="roller surface speed")
    ax2.plot(t, res.wheelset_speed, label="wheel surface speed")
    ax2.set_xlabel("time [s]")
    ax2.set_ylabel("speed [m/s]")
    ax2.legend(fontsize=8, loc="lower right")
    ax2.grid(alpha=0.3)
    mu0 = res.params["scenario"]["mu0"]
    fig.suptitle(f"Braking under creepage control (mu0 = {mu0}, dt = {res.dt * 1e3:g} ms): "
                 "creepage and speeds (paper Fig. 7)", fontsize=10)
    fig.tight_layout()
    paths.append(os.path.join(outdir, f"{prefix}_creepage.png"))
    fig.savefig(paths[-1], dpi=130)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(8, 3.6))
    ax.plot(t, -res.fx, lw=0.8, label="adhesion (braking) force, both wheels")
    ax.plot(t, mu0 * res.normal_load, color="k", ls=":", label="mu0 N")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("force [N]")
    ax.set_ylim(0, 1.1 * mu0 * np.nanmax(res.normal_load))
    ax.legend(fontsize=8, loc="lower right")
    ax.grid(alpha=0.3)
    ax.set_title("Adhesion force (paper Fig. 8)", fontsize=10)
    fig.tight_layout()
    paths.append(os.path.join(outdir, f"{prefix}_force.png"))
    fig.savefig(paths[-1], dpi=130)
    plt.close(fig)
    return paths
