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
# What save() writes: each figure in these formats at this resolution (--formats, --dpi:
# the commands' --figures and --dpi).
SAVE = {"formats": ["png"], "dpi": DPI}
FORMATS = ("png", "pdf", "svg", "eps")


def _formats(text):
    formats = [f.strip() for f in text.split(",") if f.strip()]
    bad = [f for f in formats if f not in FORMATS]
    if bad or not formats:
        raise argparse.ArgumentTypeError("formats are a comma-separated list of %s, not %r" % (", ".join(FORMATS), text))
    return formats


def parser(doc, folder_help):
    """An ArgumentParser whose description is the script's docstring and whose one
    positional argument is the output folder to read."""
    p = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("folder", metavar="DIR", help=folder_help)
    p.add_argument("--out", metavar="OUT_DIR", help="write the figures here (default: DIR)")
    p.add_argument("--formats", type=_formats, default=["png"], metavar="LIST",
                   help="each figure in these formats, comma-separated: png, pdf, svg, eps (default png)")
    p.add_argument("--dpi", type=int, default=DPI, help="resolution of the raster formats (default %d)" % DPI)
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
    """The folder the figures go to (made), and the formats and resolution save() uses."""
    out = args.out or args.folder
    os.makedirs(out, exist_ok=True)
    SAVE["formats"], SAVE["dpi"] = args.formats, args.dpi
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
    """Saves fig as out/name in each format asked (name's extension replaced: fig3.png,
    fig3.pdf, ...), closes it and records the paths in `written` (a list). Returns the first."""
    fig.tight_layout()
    stem = os.path.splitext(name)[0]
    paths = []
    for fmt in SAVE["formats"]:
        path = os.path.join(out, stem + "." + fmt)
        fig.savefig(path, dpi=SAVE["dpi"])
        paths.append(path)
    plt.close(fig)
    if written is not None:
        written.extend(paths)
    return paths[0]


def report(written):
    for path in written:
        print(f"wrote {path}")
    sys.stdout.flush()
