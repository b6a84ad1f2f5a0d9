__all__=['contactor',
         'contactorM2',
         'contactorR2',
         'rigid_properties_2D,'
         'rigid_properties_3D',
         'contactorFactory'
         ]
