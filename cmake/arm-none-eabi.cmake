# Cross-compiling for bare-metal Cortex-M4F (the e-puck2's STM32F407, QEMU's netduinoplus2
# STM32F405) with Debian's gcc-arm-none-eabi and its newlib C library. Used by mcu/ through
# scripts/run-on-mcu.sh.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
set(CMAKE_ASM_COMPILER arm-none-eabi-gcc)
# A try_compile links nothing (there is no start-up code before mcu/ provides one).
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(ANTKIT_MCU_CPU_FLAGS "-mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16")
set(CMAKE_C_FLAGS_INIT "${ANTKIT_MCU_CPU_FLAGS}")
set(CMAKE_CXX_FLAGS_INIT "${ANTKIT_MCU_CPU_FLAGS}")
set(CMAKE_EXE_LINKER_FLAGS_INIT "${ANTKIT_MCU_CPU_FLAGS}")
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
