// The PC's end of the board's UART, 8N1, on the pins of a simulated board:
// a transmitter of a byte queue (drives the board's uart_rx) and a receiver
// that samples the board's uart_tx in the middle of each bit. Clocked in the
// caller's clock (`clocks_per_bit` of them per bit).
#pragma once

#include <cstdint>
#include <deque>
#include <vector>

namespace sc {

class UartLine {
 public:
  explicit UartLine(int clocks_per_bit) : per_bit_(clocks_per_bit) {}

  void send(uint8_t byte) { queue_.push_back({byte, true, 0}); }
  // Line faults: a byte whose stop bit is low (the receiver's framing error;
  // the line then idles high for a bit), and the line pulled low for
  // `clocks` clocks (a glitch, too short for a start bit) then high for a bit.
  void send_with_low_stop_bit(uint8_t byte) { queue_.push_back({byte, false, 0}); }
  void send_glitch(int clocks) { queue_.push_back({0, true, clocks}); }
  // The level to drive on the board's uart_rx this clock.
  bool tx_level() const { return tx_level_; }
  // Ends the clock: `board_tx` is the board's uart_tx level seen in it.
  void clock(bool board_tx) {
    clock_tx();
    clock_rx(board_tx);
  }
  bool sending() const { return tx_bit_ >= 0 || !queue_.empty(); }
  bool receiving() const { return rx_bit_ > -2; }
  // Bytes received with a good stop bit, in order; taken out.
  std::vector<uint8_t> take_received() {
    std::vector<uint8_t> out;
    out.swap(received_);
    return out;
  }
  size_t received_count() const { return received_.size(); }

 private:
  void clock_tx() {
    if (tx_bit_ < 0) {
      if (queue_.empty()) {
        tx_level_ = true;
        return;
      }
      tx_ = queue_.front();
      queue_.pop_front();
      tx_bit_ = 0;
      tx_left_ = tx_.glitch_clocks > 0 ? tx_.glitch_clocks : per_bit_;
    }
    if (tx_.glitch_clocks > 0) {  // bit 0 the glitch, bit 1 the line high again
      tx_level_ = tx_bit_ != 0;
      if (--tx_left_ == 0) {
        tx_left_ = per_bit_;
        if (++tx_bit_ > 1) tx_bit_ = -1;
      }
      return;
    }
    // bit 0 start, 1..8 data (LSB first), 9 stop, 10 idle after a low stop bit
    const int last = tx_.stop_level ? 9 : 10;
    tx_level_ = tx_bit_ == 0    ? false
                : tx_bit_ == 9  ? tx_.stop_level
                : tx_bit_ == 10 ? true
                                : ((tx_.byte >> (tx_bit_ - 1)) & 1) != 0;
    if (--tx_left_ == 0) {
      tx_left_ = per_bit_;
      if (++tx_bit_ > last) tx_bit_ = -1;
    }
  }

  void clock_rx(bool level) {
    if (rx_bit_ == -2) {  // idle: a falling edge starts a byte
      if (!level) {
        rx_bit_ = -1;
        rx_left_ = per_bit_ / 2;
      }
      return;
    }
    if (--rx_left_ > 0) return;
    rx_left_ = per_bit_;
    if (rx_bit_ == -1) {  // middle of the start bit
      if (level) {
        rx_bit_ = -2;  // a glitch, not a start bit
        return;
      }
      rx_byte_ = 0;
      rx_bit_ = 0;
    } else if (rx_bit_ < 8) {
      rx_byte_ = uint8_t(rx_byte_ | (level ? 1 : 0) << rx_bit_);
      ++rx_bit_;
    } else {
      if (level) received_.push_back(rx_byte_);  // a good stop bit
      rx_bit_ = -2;
    }
  }

  int per_bit_;
  struct Symbol {
    uint8_t byte;
    bool stop_level;
    int glitch_clocks;  // > 0: a glitch, no byte
  };
  std::deque<Symbol> queue_;
  bool tx_level_ = true;
  int tx_bit_ = -1;  // -1 idle
  int tx_left_ = 0;
  Symbol tx_{0, true, 0};
  int rx_bit_ = -2;  // -2 idle, -1 start bit, 0..7 data, 8 stop
  int rx_left_ = 0;
  uint8_t rx_byte_ = 0;
  std::vector<uint8_t> received_;
};

}  // namespace sc
