"""Why the material and friction ranges are what they are: shared by every model's declarations."""

FRICTION_WHY = ("measured coefficients of dry friction stay below about 10, clean metals in vacuum "
                "included; beyond, the contact is adhesive rather than frictional")
YOUNG_WHY = "from soft gels (1e3 Pa) to beyond diamond (1.2e12 Pa)"
DENSITY_WHY = "from aerogels (1 kg/m3) to beyond osmium (22600 kg/m3)"
