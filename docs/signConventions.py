#!/usr/bin/python3
"""Draws docs/sign-conventions.png, the picture of docs/method.md §2: a horizontal fracture,
its two sides, n_Γ, t_Γ, the traction on Ω⁺ and a slip with its sign. Run from anywhere:
    /usr/bin/python3 docs/signConventions.py
"""
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.patches import FancyArrowPatch, Rectangle

here = os.path.dirname(os.path.abspath(__file__))
fig, ax = plt.subplots(figsize=(7.5, 4.6))
ax.set_xlim(-0.2, 4.2)
ax.set_ylim(-1.35, 1.75)
ax.set_aspect("equal")
ax.axis("off")

# The two sides: Ω⁺ above (left of the walking direction), Ω⁻ below.
ax.add_patch(Rectangle((0, 0.04), 4, 1.2, color="#dbe8f5"))
ax.add_patch(Rectangle((0, -1.24), 4, 1.2, color="#f5e6d3"))
ax.plot([0.3, 3.7], [0, 0], color="k", lw=2.5)
ax.text(0.15, 1.0, "Ω⁺  (left of the walking direction)", fontsize=11)
ax.text(0.15, -1.1, "Ω⁻", fontsize=11)
ax.text(3.72, 0.08, "Γ", fontsize=13)
ax.text(0.05, 0.1, "s = 0", fontsize=9)


def arrow(x0, y0, x1, y1, color, label, lx, ly, **kw):
    ax.add_patch(FancyArrowPatch((x0, y0), (x1, y1), arrowstyle="-|>", mutation_scale=16,
                                 color=color, lw=2, **kw))
    ax.text(lx, ly, label, color=color, fontsize=11)


# Walking direction = t_Γ; n_Γ points from Ω⁺ into Ω⁻.
arrow(0.6, 0.0, 1.4, 0.0, "tab:blue", "t_Γ = (−n_y, n_x) = (1, 0)", 0.45, -0.25)
arrow(1.0, 0.0, 1.0, -0.75, "tab:red", "n_Γ = (0, −1): from Ω⁺ to Ω⁻", 1.08, -0.6)
# Traction Σ = σ n_Γ acting on Ω⁺ (from Ω⁻), split into σ_n n_Γ and τ t_Γ.
arrow(2.6, 0.0, 2.6, 0.65, "tab:purple", "σ_n n_Γ, σ_n < 0 (compression)", 2.05, 0.75)
arrow(2.6, 0.02, 3.3, 0.02, "tab:green", "τ t_Γ, τ > 0", 2.75, 0.12)
ax.text(1.75, 1.32, "traction on Ω⁺ (exerted by Ω⁻): Σ = σ n_Γ = σ_n n_Γ + τ t_Γ", fontsize=9,
        color="tab:purple")
# Slip: the jump [[u]]·t_Γ = u⁺ − u⁻; a negative slip moves Ω⁺ against t_Γ.
arrow(3.6, 0.45, 2.9, 0.45, "tab:orange", "u⁺", 3.65, 0.4)
arrow(2.9, -0.45, 3.6, -0.45, "tab:orange", "u⁻", 3.65, -0.5)
ax.text(2.05, -0.95, "slip = [[u]]·t_Γ = (u⁺ − u⁻)·t_Γ < 0 here:\n"
        "Ω⁺ moves against τ, as Coulomb's law requires", fontsize=9, color="tab:orange")
ax.set_title("Sign conventions (a horizontal fracture, walked left to right)", fontsize=11)
fig.tight_layout()
fig.savefig(os.path.join(here, "sign-conventions.png"), dpi=110)
