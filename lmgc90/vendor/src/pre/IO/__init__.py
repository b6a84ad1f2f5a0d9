# import du module permettant de savoir si on pourra importer lmgc90
from ..utilities.check_compiled_modules import *

__all__=['bodies2File'   , 'model2File' , 'drvDof2File'     , 'dofIni2File',
         'bulkBehav2File', 'gpvIni2File', 'vlocrlocIni2File', ]

