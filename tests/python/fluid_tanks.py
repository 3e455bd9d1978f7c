"""A 2D fluid block above three layers of wall particles, as PySPH's dam-break and tank
examples lay them out: the fluid jittered, with h, m and rho varying per particle, for the
tests of several particle arrays and of PySPH's pair h."""
import numpy as np


def wall_and_fluid(seed, cells, jitter, h_spread, h_wall_spread=0.0, mass_spread=0.0, with_z=True):
    """`cells` x `cells` fluid particles dx = 0.05 apart, moved by up to `jitter` dx, with
    h = 1.2 dx (1 +- h_spread) (the wall's with h_wall_spread), rho = 1000 (1 +- 0.02) and
    m = rho dx^2 (1 +- mass_spread); the wall three layers deep and three dx wider on each side."""
    rng = np.random.default_rng(seed)
    dx = 0.05
    gx, gy = np.meshgrid(np.arange(cells) * dx + dx / 2, np.arange(cells) * dx + dx / 2)
    n = gx.size
    rho = 1000 * rng.uniform(0.98, 1.02, n)
    fluid = {"x": gx.ravel() + rng.uniform(-jitter, jitter, n) * dx, "y": gy.ravel() + rng.uniform(-jitter, jitter, n) * dx,
             "h": 1.2 * dx * rng.uniform(1 - h_spread, 1 + h_spread, n), "rho": rho,
             "m": rho * dx**2 * rng.uniform(1 - mass_spread, 1 + mass_spread, n)}
    wx, wy = np.meshgrid(np.arange(-3, cells + 3) * dx + dx / 2, -np.arange(3) * dx - dx / 2)
    k = wx.size
    solid = {"x": wx.ravel(), "y": wy.ravel(), "h": 1.2 * dx * rng.uniform(1 - h_wall_spread, 1 + h_wall_spread, k),
             "rho": np.full(k, 1000.0), "m": np.full(k, 1000 * dx**2)}
    if with_z:
        fluid["z"], solid["z"] = np.zeros(n), np.zeros(k)
    return fluid, solid
