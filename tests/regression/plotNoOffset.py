#!/usr/bin/python3
"""Runs plotFracture.py (imported from the given path) with its arguments and checks that no
axis of any figure it saves uses an offset: after drawing, every scalar tick formatter
(plain axes, colorbars, secondary axes) has offset 0, so a value of -2.87e7 varying by 8e3
is labelled -2.8708e7 ... (a 1eN multiplier is fine), never "+-8000 above -2.87e7".

Usage: plotNoOffset.py PLOT_SCRIPT ARG...   (the arguments of plotFracture.py)
Prints the number of axes checked per figure; exit 1 naming the figure and the axis where an
offset is drawn, or when plotFracture fails.
"""
import importlib.util
import sys

from matplotlib.ticker import ScalarFormatter


def axesOf(fig):
    """Every axes of a figure, the secondary axes (children of an axes) included."""
    stack, seen = list(fig.axes), []
    while stack:
        ax = stack.pop()
        seen.append(ax)
        stack.extend(getattr(ax, "child_axes", []))
    return seen


def main(script, args):
    spec = importlib.util.spec_from_file_location("plotFracture", script)
    plot = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(plot)
    save = plot.saveFigure
    problems, report = [], []

    def checkedSave(fig, out):
        fig.canvas.draw()  # the formatters choose their offset when the ticks are drawn
        count = 0
        for ax in axesOf(fig):
            for name, axis in (("x", ax.xaxis), ("y", ax.yaxis)):
                formatter = axis.get_major_formatter()
                if not isinstance(formatter, ScalarFormatter) or not axis.get_visible():
                    continue
                count += 1
                if formatter.offset != 0:
                    problems.append(f"{out}: {name} axis '{axis.get_label_text()}' of "
                                    f"'{ax.get_title()}' drawn with the offset "
                                    f"{formatter.get_offset()}")
        report.append(f"{out}: {count} scalar axes, no offset")
        save(fig, out)

    plot.saveFigure = checkedSave
    try:
        plot.main(args)
    except plot.PlotError as e:
        print(f"plotNoOffset: plotFracture failed: {e}")
        return 1
    for line in problems:
        print(f"plotNoOffset: {line}")
    if problems:
        return 1
    if not report:
        print("plotNoOffset: no figure written")
        return 1
    for line in report:
        print(f"  {line}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2:]))
