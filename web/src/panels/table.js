// Key-value tables and row tables whose cells are created once and then only get new text, so a
// 10 Hz status stream does not rebuild the DOM.

/** A two-column table of labelled values: rows = [[label, (msg) => text, (msg) => className?]]. */
export class KeyValueTable {
  constructor(container, rows) {
    this.rows = rows;
    this.cells = [];
    const table = document.createElement('table');
    table.className = 'kv';
    for (const [label] of rows) {
      const tr = table.insertRow();
      const th = document.createElement('th');
      th.textContent = label;
      tr.appendChild(th);
      const td = tr.insertCell();
      td.textContent = '—';
      this.cells.push(td);
    }
    container.appendChild(table);
  }

  update(message) {
    for (let i = 0; i < this.rows.length; i++) {
      const [, text, cls] = this.rows[i];
      let value;
      try {
        value = text(message);
      } catch {
        value = '—';
      }
      const cell = this.cells[i];
      if (cell.textContent !== value) cell.textContent = value;
      const className = cls ? cls(message) || '' : '';
      if (cell.className !== className) cell.className = className;
    }
  }
}

/** A table with a header and one row per item: columns = [[header, (item) => text, cls?]]. */
export class RowTable {
  constructor(table, columns) {
    this.columns = columns;
    this.table = table;
    const head = table.createTHead().insertRow();
    for (const [header] of columns) {
      const th = document.createElement('th');
      th.textContent = header;
      head.appendChild(th);
    }
    this.body = table.createTBody();
  }

  update(items) {
    while (this.body.rows.length > items.length) this.body.deleteRow(-1);
    while (this.body.rows.length < items.length) {
      const tr = this.body.insertRow();
      for (let c = 0; c < this.columns.length; c++) tr.insertCell();
    }
    for (let r = 0; r < items.length; r++) {
      const tr = this.body.rows[r];
      for (let c = 0; c < this.columns.length; c++) {
        const [, text, cls] = this.columns[c];
        let value;
        try {
          value = text(items[r]);
        } catch {
          value = '—';
        }
        const cell = tr.cells[c];
        if (cell.textContent !== value) cell.textContent = value;
        const className = cls ? cls(items[r]) || '' : '';
        if (cell.className !== className) cell.className = className;
      }
    }
  }
}

/** Class for a state name: good / warn / bad / (none). */
export function stateClass(name) {
  const s = String(name || '').toUpperCase();
  if (/FAIL|FAULT|ERROR|ABORT|BUS-OFF|BACKOFF|EXITED|STOPPED/.test(s)) return 'bad';
  if (/STOPPING|HELD|WARN|PASSIVE|PLANNING|STARTING|ENABLING|RECOVERING|WAITING|CANCELLED/.test(s)) return 'warn';
  if (/SUCCEEDED|RUNNING|TRACKING|FINISHED|OK|ACTIVE|OPERATION ENABLED|OPERATIONAL/.test(s)) return 'good';
  return '';
}
