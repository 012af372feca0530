"""asperity: mechanics of rough, loaded, lubricated contacts.

Frictional contact (traction, microslip, twisting moment, gross slip), rough surfaces
(generation, measured data, roughness parameters, machining models), dry normal contact of rough
bodies, and steady and transient mixed elastohydrodynamic lubrication.
"""

from .errors import InputError
from .materials import STEEL, Material

__all__ = ["InputError", "Material", "STEEL", "__version__"]

__version__ = "0.1.0"
