from . import impact as impact, lamb as lamb, wedge as wedge
from ._dyncontact import InvalidParameterError as InvalidParameterError, NumericalError as NumericalError, get_num_threads as get_num_threads, set_num_threads as set_num_threads
from ._sweep import cases as cases, sweep as sweep

__all__ = ['wedge', 'impact', 'lamb', 'sweep', 'cases', 'set_num_threads', 'get_num_threads', 'InvalidParameterError', 'NumericalError', '__version__']

__version__: str
