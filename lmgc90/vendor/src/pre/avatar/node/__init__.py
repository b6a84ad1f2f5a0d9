__all__=['node',
         'dof',
        ]
