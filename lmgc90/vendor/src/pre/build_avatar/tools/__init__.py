__all__=['containers2D', 'containers3D','granulometry']
