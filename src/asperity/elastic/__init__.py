"""The elastic half-space: influence coefficients and their FFT convolutions."""

from .convolution import (
    Convolution,
    grid_spacing,
    normal_operator,
    padded_shape,
    periodic_halfspace_spectrum,
    periodic_tangential_spectra,
)
from .differential import differential_coefficients, line_differential_coefficients
from .kernels import (
    TangentialInfluence,
    cerruti_integrals,
    love_integral,
    normal_influence,
    tangential_influence,
    tangential_transfer,
)

__all__ = [
    "differential_coefficients", "line_differential_coefficients",
    "Convolution",
    "TangentialInfluence",
    "cerruti_integrals",
    "grid_spacing",
    "love_integral",
    "normal_influence",
    "normal_operator",
    "padded_shape",
    "periodic_halfspace_spectrum",
    "periodic_tangential_spectra",
    "tangential_influence",
    "tangential_transfer",
]
