// A syntax error on line 3.
function initialize() {
  var a = [1, 2;
}
