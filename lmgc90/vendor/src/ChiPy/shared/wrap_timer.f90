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
MODULE wrap_timer
  
  USE ISO_C_BINDING

  USE timer, ONLY: &
       initialize_utimer, &
       write_utimer, &
       get_new_utimer_ID, &
       start_utimer,stop_utimer, &
       clear_all

  PUBLIC

CONTAINS

!!!------------------------------------------------------------------------------------------------
    SUBROUTINE InitializeTimers() bind(c, name='timer_InitializeTimers')
      IMPLICIT NONE

       CALL initialize_utimer

    END SUBROUTINE

    SUBROUTINE WriteOutTimers() bind(c, name='timer_WriteOutTimers')
      IMPLICIT NONE

       CALL write_utimer     

    END SUBROUTINE

    integer(C_INT) function GetNewTimer(name) bind(c, name='timer_GetNewTimer')
      implicit none
      CHARACTER(C_CHAR), dimension(20) :: name

      integer :: i
      CHARACTER(len=20) :: namef

      namef = ''
      do i = 1, size(name)
         if (name(i) == C_NULL_CHAR) exit
        namef = namef(1:i-1) // name(i)
      end do

      GetNewTimer = get_new_utimer_ID(namef)

    end function

    SUBROUTINE StartTimer(ID) bind(c, name='timer_StartTimer')
      implicit none
      integer(C_INT), INTENT(IN), VALUE :: ID

      CALL start_utimer(ID)

    END SUBROUTINE

    SUBROUTINE StopTimer(ID) bind(c, name='timer_StopTimer')
      implicit none
      integer(C_INT), INTENT(IN), VALUE :: ID

      CALL stop_utimer(ID)

    END SUBROUTINE

    subroutine clearAll() bind(c, name='timer_ClearAll')
      implicit none

      call clear_all()

    end subroutine

END MODULE wrap_timer
