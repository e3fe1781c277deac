"""What the plot scripts share: argument parsing, opening an output file with a clear error,
the figure style and saving. Uses Debian's python3-matplotlib, python3-h5py and python3-numpy
(the system python, /usr/bin/python3; ./setup.sh installs them)."""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402,F401  (re-exported for the scripts)

DPI = 130
plt.rcParams.update({"font.size": 10, "axes.titlesize": 11, "legend.fontsize": 9, "figure.dpi": DPI})


def parser(doc, folder_help):
    """An ArgumentParser whose description is the script's docstring and whose one
    positional argument is the output folder to read."""
    p = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("folder", metavar="DIR", help=folder_help)
    p.add_argument("--out", metavar="OUT_DIR", help="write the PNGs here (default: DIR)")
    return p


def input_file(p, folder, name, produced_by):
    """DIR/name, or a clear argparse error (exit 2) naming what is missing and what writes it."""
    if not os.path.isdir(folder):
        p.error(f"{folder}: no such folder (give the output folder of {produced_by})")
    path = os.path.join(folder, name)
    if not os.path.isfile(path):
        p.error(f"{path}: no such file (is {folder} the output folder of {produced_by}?)")
    return path


def out_dir(args):
    out = args.out or args.folder
    os.makedirs(out, exist_ok=True)
    return out


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def style(ax, xlabel, ylabel, legend=True):
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    if legend and ax.get_legend_handles_labels()[0]:
        ax.legend()
    ax.grid(alpha=0.3)


def save(fig, out, name, written=None):
    """Saves fig as out/name, closes it and records the path in `written` (a list)."""
    fig.tight_layout()
    path = os.path.join(out, name)
    fig.savefig(path, dpi=DPI)
    plt.close(fig)
    if written is not None:
        written.append(path)
    return path


def report(written):
    for path in written:
        print(f"wrote {path}")
    sys.stdout.flush()
