__all__=['nTree', 'error', 'variables','check_compiled_modules']
