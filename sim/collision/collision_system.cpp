#include "collision_system.h"
// Placeholder translation unit while the collision stage is being written.
