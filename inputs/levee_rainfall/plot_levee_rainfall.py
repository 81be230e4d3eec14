#!/usr/bin/python3
"""Figures and key numbers of the levee rainfall scene.

  plot_levee_rainfall.py [--results DIR] [--figures DIR] [--times T ...]

The same figures as ../levee_drawdown/plot_levee_drawdown.py (which this script runs with
--name levee_rainfall): levee_rainfall_history.png (probes and kinetic energy) and
levee_rainfall_map.png (displacement of the points), from results/levee_rainfall.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                                "levee_drawdown"))
import plot_levee_drawdown  # noqa: E402

if __name__ == "__main__":
    plot_levee_drawdown.main("levee_rainfall")
