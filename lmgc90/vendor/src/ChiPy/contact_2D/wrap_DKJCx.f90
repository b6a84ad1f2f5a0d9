!===========================================================================
!
! Copyright 2000-2025 CNRS-UM.
!
! This file is part of a software (LMGC90) which is a computer program 
! which purpose is to modelize interaction problems (contact, multi-Physics,etc).
!
! This software is governed by the CeCILL license under French law and
! abiding by the rules of distribution of free software.  You can  use, 
! modify and/ or redistribute the software under the terms of the CeCILL
! license as circulated by CEA, CNRS and INRIA at the following URL
! "http://www.cecill.info". 
!
! As a counterpart to the access to the source code and  rights to copy,
! modify and redistribute granted by the license, users are provided only
! with a limited warranty  and the software's author,  the holder of the
! economic rights,  and the successive licensors  have only  limited
! liability. 
!
! In this respect, the user's attention is drawn to the risks associated
! with loading,  using,  modifying and/or developing or reproducing the
! software by the user in light of its specific status of free software,
! that may mean  that it is complicated to manipulate,  and  that  also
! therefore means  that it is reserved for developers  and  experienced
! professionals having in-depth computer knowledge. Users are therefore
! encouraged to load and test the software's suitability as regards their
! requirements in conditions enabling the security of their systems and/or 
! data to be ensured and,  more generally, to use and operate it in the 
! same conditions as regards security. 
!
! The fact that you are presently reading this means that you have had
! knowledge of the CeCILL license and that you accept its terms.
!
! To report bugs, suggest enhancements, etc. to the Authors, contact
! Frederic Dubois.
!
! frederic.dubois@umontpellier.fr
!
!===========================================================================
module wrap_DKJCx

  use ISO_C_BINDING

  use DKJCx,only: &
       smooth_computation_DKJCx, &
       compute_box_DKJCx, &
       read_ini_Vloc_Rloc_DKJCx, &
       write_xxx_Vloc_Rloc_DKJCx, &
       display_prox_tactors_DKJCx, &
       coor_prediction_DKJCx, &
       set_friction_model_DKJCx, &
       creation_tab_visu_DKJCx, &
       compute_contact_DKJCx, &
       RUN_DKJCx, &
       CHECK_DKJCx, &
       get_write_Vloc_Rloc_DKJCx, &
       set_surface_sectors_DKJCx, &
       compute_stress_DKJCx     , &
       clean_memory_DKJCx
  
  use utilities, only: faterr
  
contains
  
  subroutine SelectProxTactors(reset) bind(c, name='DKJCx_SelectProxTactors')
    use timer
    !! PURPOSE
    !!  contact detection between DISKx and JONCx tactors.
    !!  first recup coordinate prediction, then proceed to a box selection to found rough
    !!  contact list and finally compute the final contact list
    implicit none
    integer(kind=c_int), intent(in), value :: reset
    !
    logical :: is_initialized=.false.
    integer(kind=4), save :: timer_id = 0

    if( reset /= 0 ) then
      is_initialized = .false.
      return
    end if

    if( .not. check_DKJCx() ) return

                                                     !12345678901234567890
    if( timer_id == 0 ) timer_id = get_new_itimer_ID('[DKJCx] select      ')
    call start_itimer(timer_id)

    if (.not. is_initialized) then
      call compute_box_DKJCx
      is_initialized = .true.
    endif

    call coor_prediction_DKJCx
       
    if (RUN_DKJCx()) call creation_tab_visu_DKJCx

    call compute_contact_DKJCx

    call stop_itimer(timer_id)

  end subroutine

!!!--------------------------------------------------

  subroutine SmoothForceComputation() bind(c, name='DKJCx_SmoothForceComputation')
    implicit none
       !! PURPOSE
       !!  recup values of local contact forces of the last time step

       if( .not. check_DKJCx() ) return

       call smooth_computation_DKJCx

  end subroutine

!!!----------------------------------------------------

  subroutine WriteLastVlocRloc() bind(c, name='DKJCx_WriteLastVlocRloc')
    implicit none
       !! PURPOSE
       !!  write last local values (relative velocity, forces, local frame) of all
       !!  DKJCx contacts

       if( .not. check_DKJCx() ) return

       call write_xxx_Vloc_Rloc_DKJCx(2)

  end subroutine
   
  subroutine WriteOutVlocRloc() bind(c, name='DKJCx_WriteOutVlocRloc')
    implicit none
    logical      :: write_Vloc_Rloc
       !! PURPOSE
       !!  write local values (relative velocity, forces, local frame) of all
       !!  DKJCx contacts

       if( .not. check_DKJCx() ) return

       write_Vloc_Rloc = get_write_Vloc_Rloc_DKJCx()

       if (write_Vloc_Rloc) call write_xxx_Vloc_Rloc_DKJCx(1)

  end subroutine
    
  subroutine DisplayOutVlocRloc() bind(c, name='DKJCx_DisplayOutVlocRloc')
    implicit none
       !! PURPOSE
       !!  display local values (relative velocity, forces, local frame) of all
       !!  DKJCx contacts

       if( .not. check_DKJCx() ) return

       call write_xxx_Vloc_Rloc_DKJCx(6)

  end subroutine

  subroutine DisplayProxTactors() bind(c, name='DKJCx_DisplayProxTactors')
    implicit none
       !! PURPOSE
       !!  display contacts

       if( .not. check_DKJCx() ) return

       call display_prox_tactors_DKJCx

  end subroutine

  subroutine ReadIniVlocRloc(step) bind(c, name='DKJCx_ReadIniVlocRloc')
    implicit none
    integer(c_int), intent(in), value :: step

     if( .not. check_DKJCx() ) return

     call read_ini_Vloc_Rloc_DKJCx(step)

  end subroutine

   subroutine SetSurfaceSectorsDKJCx(nbsect) bind(c, name='DKJCx_SetSurfaceSectors')
     implicit none
     integer(c_int),intent(in), value :: nbsect

     call set_surface_sectors_DKJCx(nbsect)

   end subroutine SetSurfaceSectorsDKJCx

   subroutine ComputeStressDKJCx() bind(c, name='DKJCx_ComputeStress')
     implicit none

     call compute_stress_DKJCx()
     
   end subroutine ComputeStressDKJCx

    subroutine CleanMemory() bind(c, name='DKJCx_CleanMemory')
      implicit none

      call clean_memory_DKJCx
      !call SelectProxTactors(reset=1)
      call SelectProxTactors(1)

    end subroutine
!!!--------------------------------------------------
  subroutine SetFrictionModel(cvalue1_c) bind(c, name='DKJCx_SetFrictionModel')
    implicit none
    character(C_CHAR), dimension(3)   :: cvalue1_c
    character(len=3) :: cvalue1
    integer :: i
    
    cvalue1 = ''
    do i=1,3
       cvalue1 = cvalue1(1:i-1) // cvalue1_c(i)
    end do
    
    if( .not. check_DKJCx() ) return
    
    call set_friction_model_DKJCx(cvalue1)
    
  end subroutine SetFrictionModel  
!!!----------------------------------
  
end module wrap_DKJCx
