"""Plots of the roller slider crank (model_variant 2) in the style of Farahanchi's thesis: Poincare sections
(Fig 4.3), impact distribution profiles (Figs 4.6-4.14), impact spectra (Figs 4.16-4.17), constraint forces
(Figs 2.4-2.9) and sliding regions (Fig 2.10)."""

import matplotlib.pyplot as plt
import numpy as np

_REGION_CODES = {"none": 0, "I": 1, "II": 2, "III": 3}


def _save(fig, path):
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def _poincare(ax, points, title=None):
    theta, rate = points
    ax.plot(theta, rate, ".k", ms=1.5)
    ax.set_xlim(0, 2 * np.pi)
    ax.set_xlabel("crank angle θ [rad]")
    ax.set_ylabel("ψ' before an upper-wall impact\n[rad per rad of crank angle]")
    if title:
        ax.set_title(title, fontsize="small")


def _profile(ax, profile, title=None):
    edges, upper, lower = profile
    centres, width = (edges[:-1] + edges[1:]) / 2, np.diff(edges)
    ax.bar(centres, upper, width, color="tab:red", label="upper wall (> 0)")
    ax.bar(centres, lower, width, color="tab:blue", label="lower wall (< 0)")
    ax.axhline(0, color="k", lw=0.5)
    ax.set_xlabel("impact location x = pin position / rod length [-]")
    ax.set_ylabel("⟨ψ'(Δx)⟩, eq 3.6 [rad/rad]")
    ax.legend(fontsize="x-small", loc="upper right")
    if title:
        ax.set_title(title, fontsize="small")


def case_sheet(poincare, profile, spectra, title, path):
    """One run: Poincare section (eq 3.4), impact profile (eq 3.6) and the two impact spectra (eq 3.7)."""
    fig = plt.figure(figsize=(12, 8))
    fig.suptitle(title)
    _poincare(fig.add_subplot(2, 2, 1), poincare, "Poincaré section")
    _profile(fig.add_subplot(2, 2, 2), profile, "impact distribution profile")
    edges, upper, lower = spectra
    for k, (name, spectrum) in enumerate((("upper", upper), ("lower", lower))):
        ax = fig.add_subplot(2, 2, 3 + k, projection="polar")
        ax.bar(edges[:-1], spectrum, np.diff(edges), align="edge", color="tab:red" if k == 0 else "tab:blue")
        ax.set_title(f"impact spectrum (eq 3.7), {name} wall: Σ|ψ'| / N per crank-angle bin", fontsize="small")
    return _save(fig, path)


def forces_sheet(figures, curves, regions, path):
    """f_u, f_l over a crank cycle for each (rho, lambda) of `figures` (printed f solid, corrected dashed),
    and the maps of Fig 2.10 for both forms."""
    n = len(figures)
    fig, axes = plt.subplots(2, (n + 3) // 2, figsize=(5 * ((n + 3) // 2), 8), squeeze=False)
    axes = axes.ravel()
    for ax, (name, (rho, lam)) in zip(axes, figures.items(), strict=False):
        for forcing, style in ((1, "-"), (2, "--")):
            data = curves[name, forcing]
            ax.plot(data[:, 0], data[:, 1], style, color="tab:red", label=f"f_u, forcing {forcing}")
            ax.plot(data[:, 0], data[:, 2], style, color="tab:blue", label=f"f_l, forcing {forcing}")
        ax.axhline(0, color="k", lw=0.5)
        ax.set_xlim(0, 2 * np.pi)
        ax.set_title(f"Fig {name}: ρ={rho:g}, λ={lam:g}", fontsize="small")
        ax.set_xlabel("crank angle θ [rad]")
        ax.set_ylabel("constraint force (eq 2.29) [thesis units]")
    axes[0].legend(fontsize="x-small", title="u: upper wall, l: lower wall", title_fontsize="x-small")
    for ax, forcing in zip(axes[n:], (1, 2), strict=False):
        rows = np.array([(float(r), float(lam), _REGION_CODES[g]) for r, lam, g in regions[forcing]])
        size = round(np.sqrt(len(rows)))
        grid = rows[:, 2].reshape(size, size)
        image = ax.imshow(
            grid.T,
            origin="lower",
            aspect="auto",
            cmap="viridis",
            vmin=0,
            vmax=3,
            extent=(0, rows[:, 0].max(), 0, rows[:, 1].max()),
        )
        ax.set_xlabel("clearance ρ [-]")
        ax.set_ylabel("damping λ [-]")
        ax.set_title(f"Fig 2.10, forcing {forcing}: regions 0 none, I, II, III", fontsize="small")
        fig.colorbar(image, ax=ax, ticks=[0, 1, 2, 3])
    for ax in axes[n + 2 :]:
        ax.axis("off")
    return _save(fig, path)


def thesis_sheet(cases, path):
    """Impact profile and Poincare section of every chapter-4 run: `cases` = [(run, response, profile, points)]."""
    cols = 5
    rows = (len(cases) + cols - 1) // cols
    fig, axes = plt.subplots(2 * rows, cols, figsize=(4 * cols, 5.6 * rows), squeeze=False)
    for k, (run, response, profile, points) in enumerate(cases):
        r, c = divmod(k, cols)
        title = f"λ={run.lam:g} ρ={run.rho:g} e={run.e:g}\n{response.kind}" + (
            f" P{response.period}" if response.period else ""
        )
        _profile(axes[2 * r, c], profile, title)
        _poincare(axes[2 * r + 1, c], points)
    for k in range(len(cases), rows * cols):
        r, c = divmod(k, cols)
        axes[2 * r, c].axis("off")
        axes[2 * r + 1, c].axis("off")
    return _save(fig, path)
