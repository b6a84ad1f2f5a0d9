__all__=['bulk',
         'element',
         'rigid2d',
         'rigid3d'
         ]
