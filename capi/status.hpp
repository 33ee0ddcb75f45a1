// SPDX-License-Identifier: MIT
// The thread's last status and message, set by every entry point.
#pragma once

#include <impulse2d/base.h>

namespace i2d::capi {

void set_ok();
/// Records a failure; the message is "<function>: <formatted detail>".
void set_error(i2d_status status, const char* function, const char* format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
i2d_status last_status();

}  // namespace i2d::capi
