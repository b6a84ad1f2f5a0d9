
novisu    = False
nowarning = False
