__all__ = [ 'group',
          ]
