module sub(input clk, input [7:0] a, b, output reg [15:0] y);
  reg [7:0] mem [0:255];
  reg [7:0] q;
  always @(posedge clk) begin y <= a * b + q; q <= mem[a]; mem[b] <= a; end
endmodule
module top(input clk, input [7:0] a, b, output [15:0] y, output reg [8:0] s);
  sub u(clk, a, b, y);
  always @(posedge clk) s <= a + b;
endmodule
