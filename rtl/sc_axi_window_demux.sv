// sc_axi_window_demux: one AXI4-Lite slave port in front of Slaves register
// windows of 2^sc_pkg::RegAddrW bytes each (the register files of a
// multi-axis map, sc_axi_multi_axis).
//
// The upper address bits (window w = addr >> RegAddrW) pick the target:
// window 0 is the group window, window 1 + s is slave s. A write to the
// group window goes to every slave in the same clock (group_o = 1 while it
// is in flight), and answers once all of them have answered, with the worst
// response (DECERR > SLVERR > OKAY: the OR of the codes). A read of the
// group window reads slave 0. A window above Slaves answers DECERR here and
// reaches no slave.
//
// One write and one read in flight, as in sc_axi_regs: AW and W are held
// (in any order) until both are here, then issued to the targets for one
// clock, and held until the master takes the response. The slaves are
// idle whenever a request is issued, so they take it in that clock; they
// are identical register files, so a group write's responses all arrive
// in one clock.
module sc_axi_window_demux #(
  parameter int Slaves = 2
) (
  input  logic                               clk_i,
  input  logic                               rst_ni,

  // from the master
  input  logic [sc_pkg::MultiRegAddrW-1:0]   s_axi_awaddr_i,
  input  logic                               s_axi_awvalid_i,
  output logic                               s_axi_awready_o,
  input  logic [31:0]                        s_axi_wdata_i,
  input  logic [3:0]                         s_axi_wstrb_i,
  input  logic                               s_axi_wvalid_i,
  output logic                               s_axi_wready_o,
  output logic [1:0]                         s_axi_bresp_o,
  output logic                               s_axi_bvalid_o,
  input  logic                               s_axi_bready_i,
  input  logic [sc_pkg::MultiRegAddrW-1:0]   s_axi_araddr_i,
  input  logic                               s_axi_arvalid_i,
  output logic                               s_axi_arready_o,
  output logic [31:0]                        s_axi_rdata_o,
  output logic [1:0]                         s_axi_rresp_o,
  output logic                               s_axi_rvalid_o,
  input  logic                               s_axi_rready_i,

  // to the slaves: one address, data and strobe for all, a valid each
  output logic [sc_pkg::RegAddrW-1:0]        m_axi_awaddr_o,
  output logic [Slaves-1:0]                  m_axi_awvalid_o,
  output logic [31:0]                        m_axi_wdata_o,
  output logic [3:0]                         m_axi_wstrb_o,
  output logic [Slaves-1:0]                  m_axi_wvalid_o,
  input  logic [Slaves*2-1:0]                m_axi_bresp_i,
  input  logic [Slaves-1:0]                  m_axi_bvalid_i,
  output logic [Slaves-1:0]                  m_axi_bready_o,
  output logic [sc_pkg::RegAddrW-1:0]        m_axi_araddr_o,
  output logic [Slaves-1:0]                  m_axi_arvalid_o,
  input  logic [Slaves*32-1:0]               m_axi_rdata_i,
  input  logic [Slaves*2-1:0]                m_axi_rresp_i,
  input  logic [Slaves-1:0]                  m_axi_rvalid_i,
  output logic [Slaves-1:0]                  m_axi_rready_o,
  output logic                               group_o       // the write in flight is the group window's
);

  localparam int AW  = sc_pkg::RegAddrW;
  localparam int MAW = sc_pkg::MultiRegAddrW;
  localparam int WinW = MAW - AW;
  localparam int SelW = Slaves > 1 ? $clog2(Slaves) : 1;
  localparam logic [1:0] RespDecErr = 2'b11;

`ifndef SYNTHESIS
  initial begin
    if (Slaves < 1 || Slaves >= 2 ** WinW) $fatal(1, "sc_axi_window_demux: Slaves=%0d does not fit %0d window bits",
                                                 Slaves, WinW);
  end
`endif

  logic              aw_full_q, aw_full_d, w_full_q, w_full_d, w_sent_q, w_sent_d, b_own_q, b_own_d;
  logic [MAW-1:0]    awaddr_q, awaddr_d;
  logic [31:0]       wdata_q, wdata_d;
  logic [3:0]        wstrb_q, wstrb_d;
  logic              ar_full_q, ar_full_d, r_sent_q, r_sent_d, r_own_q, r_own_d;
  logic [MAW-1:0]    araddr_q, araddr_d;

  logic [WinW-1:0]   w_win, r_win;
  logic              w_known, r_known, w_issue, r_issue, b_all, b_done, r_done;
  logic [Slaves-1:0] w_sel;
  logic [SelW-1:0]   r_idx;
  logic [1:0]        b_worst;

  assign w_win   = awaddr_q[MAW-1:AW];
  assign r_win   = araddr_q[MAW-1:AW];
  assign w_known = w_win <= WinW'(Slaves);
  assign r_known = r_win <= WinW'(Slaves);
  assign group_o = w_win == '0;
  assign r_idx   = (r_win == '0 || !r_known) ? '0 : SelW'(r_win - WinW'(1));
  always_comb begin
    for (int s = 0; s < Slaves; s++) w_sel[s] = group_o || w_win == WinW'(s + 1);
  end

  assign w_issue = aw_full_q && w_full_q && !w_sent_q && !b_own_q;
  assign r_issue = ar_full_q && !r_sent_q && !r_own_q;

  // a group write answers when every slave has: all at once
  assign b_all = &(m_axi_bvalid_i | ~w_sel);
  always_comb begin
    b_worst = '0;
    for (int s = 0; s < Slaves; s++) if (w_sel[s]) b_worst = b_worst | m_axi_bresp_i[2*s +: 2];
  end

  assign s_axi_awready_o = !aw_full_q;
  assign s_axi_wready_o  = !w_full_q;
  assign s_axi_bvalid_o  = b_own_q || (w_sent_q && b_all);
  assign s_axi_bresp_o   = b_own_q ? RespDecErr : b_worst;
  assign s_axi_arready_o = !ar_full_q;
  assign s_axi_rvalid_o  = r_own_q || (r_sent_q && m_axi_rvalid_i[r_idx]);
  assign s_axi_rresp_o   = r_own_q ? RespDecErr : m_axi_rresp_i[2*r_idx +: 2];
  assign s_axi_rdata_o   = r_own_q ? '0 : m_axi_rdata_i[32*r_idx +: 32];

  assign b_done = s_axi_bvalid_o && s_axi_bready_i;
  assign r_done = s_axi_rvalid_o && s_axi_rready_i;

  assign m_axi_awaddr_o  = awaddr_q[AW-1:0];
  assign m_axi_wdata_o   = wdata_q;
  assign m_axi_wstrb_o   = wstrb_q;
  assign m_axi_awvalid_o = (w_issue && w_known) ? w_sel : '0;
  assign m_axi_wvalid_o  = (w_issue && w_known) ? w_sel : '0;
  assign m_axi_bready_o  = (w_sent_q && b_all && s_axi_bready_i) ? w_sel : '0;
  assign m_axi_araddr_o  = araddr_q[AW-1:0];
  always_comb begin
    m_axi_arvalid_o = '0;
    m_axi_rready_o  = '0;
    m_axi_arvalid_o[r_idx] = r_issue && r_known;
    m_axi_rready_o[r_idx]  = r_sent_q && s_axi_rready_i;
  end

  always_comb begin
    aw_full_d = aw_full_q;
    awaddr_d  = awaddr_q;
    w_full_d  = w_full_q;
    wdata_d   = wdata_q;
    wstrb_d   = wstrb_q;
    w_sent_d  = w_sent_q;
    b_own_d   = b_own_q;
    ar_full_d = ar_full_q;
    araddr_d  = araddr_q;
    r_sent_d  = r_sent_q;
    r_own_d   = r_own_q;
    if (s_axi_awvalid_i && !aw_full_q) begin
      aw_full_d = 1'b1;
      awaddr_d  = s_axi_awaddr_i;
    end
    if (s_axi_wvalid_i && !w_full_q) begin
      w_full_d = 1'b1;
      wdata_d  = s_axi_wdata_i;
      wstrb_d  = s_axi_wstrb_i;
    end
    if (w_issue) begin
      w_sent_d = w_known;
      b_own_d  = !w_known;
    end
    if (b_done) begin
      aw_full_d = 1'b0;
      w_full_d  = 1'b0;
      w_sent_d  = 1'b0;
      b_own_d   = 1'b0;
    end
    if (s_axi_arvalid_i && !ar_full_q) begin
      ar_full_d = 1'b1;
      araddr_d  = s_axi_araddr_i;
    end
    if (r_issue) begin
      r_sent_d = r_known;
      r_own_d  = !r_known;
    end
    if (r_done) begin
      ar_full_d = 1'b0;
      r_sent_d  = 1'b0;
      r_own_d   = 1'b0;
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      aw_full_q <= 1'b0;
      awaddr_q  <= '0;
      w_full_q  <= 1'b0;
      wdata_q   <= '0;
      wstrb_q   <= '0;
      w_sent_q  <= 1'b0;
      b_own_q   <= 1'b0;
      ar_full_q <= 1'b0;
      araddr_q  <= '0;
      r_sent_q  <= 1'b0;
      r_own_q   <= 1'b0;
    end else begin
      aw_full_q <= aw_full_d;
      awaddr_q  <= awaddr_d;
      w_full_q  <= w_full_d;
      wdata_q   <= wdata_d;
      wstrb_q   <= wstrb_d;
      w_sent_q  <= w_sent_d;
      b_own_q   <= b_own_d;
      ar_full_q <= ar_full_d;
      araddr_q  <= araddr_d;
      r_sent_q  <= r_sent_d;
      r_own_q   <= r_own_d;
    end
  end

endmodule
