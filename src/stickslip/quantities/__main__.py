"""``python -m stickslip.quantities``: the documentation's parameter tables, on stdout."""

from . import DOMAINS
from .tables import markdown

print(markdown(DOMAINS), end="")
