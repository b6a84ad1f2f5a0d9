
from .macro import OpenCentralKernelFiles , \
                   WriteCentralKernelFiles

