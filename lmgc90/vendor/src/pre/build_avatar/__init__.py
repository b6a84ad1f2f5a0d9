# import du module permettant de savoir si on pourra importer lmgc90
from ..utilities.check_compiled_modules import *

__all__ = ['brick', 'extrusion', 'readMesh'  , 'lecture'   ,
           'mesh' , 'mesh2D'   , 'mesh3D'    , 'particles' ,
           'tools', 'walls'    , 'lattices2D', 'lattices3D',
          ]

