
is_vtk_display = False
vtkVersion     = (0,0,)
