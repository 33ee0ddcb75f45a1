// SPDX-License-Identifier: MIT
// The one error the binding throws: the library's status name and its message.

const STATUS_NAMES = [
  'I2D_OK',
  'I2D_ERR_INVALID_ARGUMENT',
  'I2D_ERR_INVALID_HANDLE',
  'I2D_ERR_WORLD_LOCKED',
  'I2D_ERR_CAPACITY',
  'I2D_ERR_OUT_OF_MEMORY',
  'I2D_ERR_INTERNAL',
  'I2D_ERR_INVALID_SNAPSHOT',
];

export class Impulse2dError extends Error {
  /**
   * @param {number} status the i2d_status code
   * @param {string} message i2d_last_error_message() at the time of the refusal
   */
  constructor(status, message) {
    super(message || STATUS_NAMES[status] || `status ${status}`);
    this.name = 'Impulse2dError';
    this.status = STATUS_NAMES[status] ?? `status ${status}`;
    this.code = status;
  }
}
