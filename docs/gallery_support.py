"""The gallery's image scraper: the package draws on `matplotlib.figure.Figure` objects without
pyplot (it never touches the user's backend), so sphinx-gallery's own scraper, which asks
pyplot for its figures, sees none. This one takes every figure a block of a gallery script left
in the script's variables (a figure, or a list of them) and not shown yet."""

from __future__ import annotations


class FigureScraper:
    """A sphinx-gallery image scraper for figures held in a script's variables."""

    def __repr__(self) -> str:  # sphinx-gallery keys its cache on this
        return "stickslip.FigureScraper"

    def __call__(self, block, block_vars, gallery_conf) -> str:
        from matplotlib.figure import Figure
        from sphinx_gallery.scrapers import figure_rst

        shown = block_vars.setdefault("stickslip_shown", [])
        found = []
        for value in list(block_vars["example_globals"].values()):
            for item in value if isinstance(value, (list, tuple)) else (value,):
                if isinstance(item, Figure) and not any(item is s for s in shown + found):
                    found.append(item)
        paths = []
        for fig, path in zip(found, block_vars["image_path_iterator"]):
            fig.savefig(path, dpi=96, bbox_inches="tight")
            paths.append(path)
        shown.extend(found)
        return figure_rst(paths, gallery_conf["src_dir"])
