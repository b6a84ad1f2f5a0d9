
module dummy_module
  implicit none

  private dummy_function

  contains

  subroutine dummy_function()
    implicit none
    ! do nothing
  end subroutine

end module dummy_module
