__all__=['avatar',
         'bulks', 'bulk',
         'nodes', 'node',
         'contactors', 'contactor',
         'groups','group'
        ]
