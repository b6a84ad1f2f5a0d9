
from .macro import *
from . import computation

Initialize()

